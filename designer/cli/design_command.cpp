// feedflow design <case>: the designer's answer to a case file.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "designer/bench/bench_run.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/cli/report_files.hpp"
#include "designer/design/design_check.hpp"
#include "designer/simulate/simulation_pictures.hpp"
#include "designer/simulate/solver_choice.hpp"
#include "designer/verify/design_verification.hpp"
#include "models/core/errors.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"
#include "reports/results_json.hpp"
#include "reports/text_summary.hpp"

namespace feedflow {
namespace {

struct DesignArguments {
  std::string case_file;
  CommandOptions options;
  bool report = false;
  std::vector<std::string> models;  // --model key=name
  std::string verify = "off";       // off | auto | cel | dem
  std::string budget = "10 min";
  std::string tolerance = "10%";
  std::string width_tolerance = "1 mm";
  std::string thickness_tolerance;
  std::string start_from;  // an earlier record of the chute's --verify dem
};

int run_design(const DesignArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<SetOverride> overrides;
  for (const auto& s : args.options.sets) overrides.push_back(parse_set_override(s));

  const ModelChoices models = ModelChoices::parse(args.models);
  const Case c = load_case(args.case_file, overrides);
  if (!args.options.quiet)
    for (const auto& w : c.warnings) std::cerr << "feedflow: warning: " << w << '\n';
  if (args.options.verbose)
    std::cerr << "feedflow: material " << c.material.name << " from " << c.material.origin << '\n';

  DesignRecord record = design_check(c, models);
  const std::filesystem::path verify_runs =
      (args.options.out.empty()
           ? std::filesystem::path("out") / (safe_folder_name(c.name) + "_verify")
           : std::filesystem::path(args.options.out) / "verify");
  VerificationRequest verify{args.case_file,
                             args.options.sets,
                             args.verify,
                             args.budget,
                             args.tolerance,
                             args.width_tolerance,
                             args.thickness_tolerance,
                             args.start_from,
                             verify_runs,
                             args.options.human_output() ? &std::cout : nullptr};
  if (!verify_design(verify, c, record)) {
    std::cerr << continue_after_interrupt(verify_runs);
    return kExitInterrupted;
  }
  record.command_line = invocation();
  record.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto folder = output_folder(args.options, c.name, "", args.report);
  if (folder)  // the runs as seen from the results file, so the folder can move with them
    for (auto& run : record.simulation_runs)
      run = std::filesystem::absolute(run)
                .lexically_relative(std::filesystem::absolute(*folder))
                .string();
  const std::string summary = text_summary(record);
  const std::string json = to_json(record).dump(2) + "\n";
  auto files = results_files(folder, json, summary, args.options);
  if (args.report)
    for (auto& file : report_files(*folder, record, record_pictures(record, *folder, std::cerr)))
      files.push_back(std::move(file));
  std::optional<OutputFolder> claimed;
  if (folder) claimed.emplace(*folder, "--out");
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json : nullptr,
                                     args.options.verbose, claimed ? &*claimed : nullptr);

  if (args.options.human_output()) {
    std::cout << summary << "\nWritten: ";
    for (std::size_t i = 0; i < written.size(); ++i)
      std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
  return verdict_exit_code(args.options, record.verdict.status);
}

}  // namespace

void add_design_command(Command& program, int& exit_code) {
  auto args = std::make_shared<DesignArguments>();
  auto command =
      program.subcommand("design", "answer the design questions of a case from the reduced models");
  command.option("case", args->case_file, "case file (TOML), e.g. cases/pilot_hopper.toml")
      .required()
      .type_name("CASE");
  add_case_options(command, args->options,
                   "out/<case name>; none with --json - unless --report asks for one");
  command.flag("--report", args->report, "also write report.pdf and report.html");
  command
      .option(
          "--verify", args->verify,
          "verify on a full rung: auto (the quantities whose decision is inside their band, on "
          "the seed's rung), cel (a hopper's discharge rate; a chute's or drum's answers from one "
          "continuum run), dem (a hopper's arching: at the outlet, and the critical width by "
          "bisection; a chute's stopping thickness by bisection on periodic layers; a drum's "
          "answers from one particle run), off")
      .show_default()
      .one_of({"off", "auto", "cel", "dem"})
      .type_name("RUNG");
  command.option("--budget", args->budget, "wall time a verification may take")
      .show_default()
      .type_name("TIME");
  command.option("--tolerance", args->tolerance, "error bar a verification must reach")
      .show_default()
      .type_name("FRACTION");
  command
      .option("--width-tolerance", args->width_tolerance,
              "--verify dem: width of the bracket the bisection on the outlet width stops at")
      .show_default()
      .type_name("WIDTH");
  command
      .option("--thickness-tolerance", args->thickness_tolerance,
              "--verify dem on a chute: width of the bracket the bisection on the stopping "
              "layer's thickness stops at (default one DEM sphere diameter)")
      .type_name("THICKNESS");
  command
      .option("--start-from", args->start_from,
              "--verify dem: an earlier design's results.json of the same hopper (but its "
              "outlet) or chute angle, its search finished or cut short, on this machine or "
              "another: the runs of its bracket (and a hopper's at the same outlet) are not made "
              "again, the bisection goes on inside it")
      .type_name("RESULTS.json");
  std::string model_help = "select an alternative model (repeatable):";
  for (const auto& o : model_options()) {
    model_help += "\n  " + std::string(o.key) + "=";
    for (std::size_t i = 0; i < o.entries.size(); ++i)
      model_help += (i ? "|" : "") + std::string(o.entries[i].name);
    model_help += " (" + std::string(o.description) + ", default " +
                  std::string(o.entries.front().name) + ")";
    for (const auto& e : o.entries)
      model_help += "\n      " + std::string(e.name) + ": " + std::string(e.summary) + " [" +
                    to_string(e.rung) + "]";
  }
  command.option("--model", args->models, model_help).type_name("KEY=NAME").repeatable();
  command.on_run([args, &exit_code] { exit_code = run_design(*args); });
}

}  // namespace feedflow
