// feedflow report <results.json>: the design report of an earlier design or simulate run.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/cli/report_files.hpp"
#include "designer/simulate/simulation_pictures.hpp"
#include "models/core/errors.hpp"
#include "reports/results_json.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

struct ReportArguments {
  std::string input;
  CommandOptions options;
};

int run_report(const ReportArguments& args) {
  const fs::path input(args.input);
  std::error_code ec;
  if (!fs::is_regular_file(input, ec)) throw InputError(args.input, "", "no such file");
  if (input.extension() == ".h5") {
    const fs::path results = input.parent_path() / "results.json";
    throw NotAvailable("a report straight from a simulation's HDF5 file (" + args.input +
                       ") is not available; make it from the run's results JSON: feedflow report " +
                       results.string());
  }
  DesignRecord record;
  try {
    std::ifstream in(input);
    record = design_record_from_json(nlohmann::ordered_json::parse(in));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(args.input, "", std::string("not valid JSON: ") + e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(args.input, "", std::string("not a feedflow results file: ") + e.what());
  }
  const fs::path folder = args.options.out.empty() ? input.parent_path() : fs::path(args.options.out);
  const auto written = write_outputs(
      report_files(folder, record, record_pictures(record, input.parent_path(), std::cerr)),
      nullptr, args.options.verbose, nullptr);
  if (!args.options.quiet) {
    std::cout << "Written: ";
    for (std::size_t i = 0; i < written.size(); ++i) std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
  return 0;
}

}  // namespace

void add_report_command(Command& program, int& exit_code) {
  auto args = std::make_shared<ReportArguments>();
  auto command = program.subcommand(
      "report", "write the PDF and HTML design report of a results JSON (from design or simulate)");
  command.option("input", args->input, "results.json written by design or simulate")
      .required()
      .type_name("FILE");
  command.option("--out", args->options.out, "output folder (default: the input's folder)")
      .type_name("DIR");
  add_verbosity_options(command, args->options, false);
  command.on_run([args, &exit_code] { exit_code = run_report(*args); });
}

}  // namespace feedflow
