// feedflow: design checks and verification simulations for bulk-solids handling equipment.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "models/core/errors.hpp"
#include "models/core/version.hpp"

int main(int argc, char** argv) {
  using namespace feedflow;
  record_invocation(argc, argv);
  CLI::App app{"feedflow: hopper, chute and drum design for bulk solids, verified by simulation",
               "feedflow"};
  app.set_version_flag("--version", std::string("feedflow ") + kVersion);
  app.require_subcommand(1);
  int exit_code = kExitOk;
  add_design_command(app, exit_code);
  add_materials_command(app, exit_code);
  add_cases_command(app, exit_code);
  add_version_command(app, exit_code);
  add_report_command(app, exit_code);
  add_element_test_command(app, exit_code);
  add_simulate_command(app, exit_code);
  add_bench_command(app, exit_code);
  add_calibrate_command(app, exit_code);
  add_sweep_command(app, exit_code);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  } catch (const InputError& e) {
    std::cerr << "feedflow: error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const NotAvailable& e) {
    std::cerr << "feedflow: " << e.what() << '\n';
    return kExitNotAvailable;
  } catch (const NumericalFailure& e) {
    std::cerr << "feedflow: numerical failure: " << e.what() << '\n';
    return kExitNumericalFailure;
  } catch (const std::exception& e) {
    std::cerr << "feedflow: internal error: " << e.what() << '\n';
    return 1;
  }
  // Text that never reached stdout (a full disk, a closed pipe) is an error, not a success.
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::cerr << "feedflow: error: cannot write to stdout (full disk or closed pipe?); the output is lost\n";
    return exit_code == kExitOk ? kExitBadInput : exit_code;
  }
  return exit_code;
}
