// feedflow: design checks and verification simulations for bulk-solids handling equipment.
#include <cstdio>
#include <iostream>

#include "designer/cli/command_line.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "models/core/errors.hpp"
#include "models/core/version.hpp"

int main(int argc, char** argv) {
  using namespace feedflow;
  record_invocation(argc, argv);
  CommandLine command_line{
      "feedflow: hopper, chute and drum design for bulk solids, verified by simulation", "feedflow",
      std::string("feedflow ") + kVersion};
  Command program = command_line.root();
  int exit_code = kExitOk;
  add_design_command(program, exit_code);
  add_materials_command(program, exit_code);
  add_cases_command(program, exit_code);
  add_version_command(program, exit_code);
  add_report_command(program, exit_code);
  add_element_test_command(program, exit_code);
  add_simulate_command(program, exit_code);
  add_bench_command(program, exit_code);
  add_calibrate_command(program, exit_code);
  add_sweep_command(program, exit_code);

  try {
    if (const auto settled = command_line.parse_and_run(argc, argv, kExitBadInput)) return *settled;
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
