// feedflow sweep <case> --vary KEY=RANGE ...: what-if analysis on the reduced rungs, every point
// answered in this process (designer/sweep/).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include <omp.h>

#include "designer/case/case_loader.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/sweep/sweep_output.hpp"
#include "fullsim/common/progress_line.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

struct SweepArguments {
  std::string case_file;
  std::vector<std::string> vary;
  std::vector<std::string> models;
  CommandOptions options;
};

int run_sweep(const SweepArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  SweepRequest request;
  for (const auto& v : args.vary) request.axes.push_back(parse_sweep_axis(v));
  for (std::size_t a = 0; a < request.axes.size(); ++a)
    for (std::size_t b = 0; b < a; ++b)
      if (request.axes[a].case_key == request.axes[b].case_key)
        throw InputError("--vary", args.vary[a], request.axes[a].key + " is varied twice");
  constexpr double kMaxPoints = 10e6;
  double points = 1.0;
  for (const auto& a : request.axes) points *= static_cast<double>(a.values.size());
  if (points > kMaxPoints)
    throw InputError("--vary", args.vary.back(),
                     "the grid has " + std::to_string(static_cast<long long>(points)) +
                         " points, more than 10 million: use coarser ranges");
  for (const auto& s : args.options.sets) request.fixed.push_back(parse_set_override(s));
  request.models = ModelChoices::parse(args.models);
  request.parsed = parse_case(args.case_file);
  const std::filesystem::path folder = std::filesystem::path(args.case_file).parent_path();
  request.materials =
      MaterialLibrary::standard(folder.empty() ? std::filesystem::path(".") : folder);
  // The case itself, with the fixed values: its faults are the case's, named as design names them.
  const Case base = load_case(request.parsed, request.fixed, request.materials);
  if (!args.options.quiet)
    for (const auto& w : base.warnings) std::cerr << "feedflow: warning: " << w << '\n';

  TerminalProgress progress = TerminalProgress::for_terminal(!args.options.human_output());
  const auto points_start = std::chrono::steady_clock::now();
  const std::vector<SweepPoint> answered = run_grid(request, progress);
  const double point_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - points_start).count();
  std::size_t refused = 0;
  for (const auto& p : answered) refused += !p.done;
  if (refused == answered.size())
    throw InputError("--vary", args.vary.front(),
                     "no point of the sweep could be checked; the first: " +
                         answered.front().error);

  SweepTiming timing;
  timing.threads = omp_get_max_threads();
  timing.point_seconds = point_seconds;
  timing.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto out = output_folder(args.options, base.name, "_sweep", true);
  const std::string json = sweep_json(request, answered, timing, invocation());
  const std::string summary = sweep_summary(request, answered, timing);
  std::vector<OutputFile> files{{*out / "sweep.json", json, "--out"},
                                {*out / "sweep.csv", sweep_csv(request, answered), "--out"},
                                {*out / "sweep.txt", summary, "--out"}};
  if (!args.options.json.empty() && !args.options.json_to_stdout())
    files.push_back({args.options.json, json, "--json"});
  OutputFolder claimed(*out, "--out");
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json : nullptr,
                                     args.options.verbose, &claimed);
  if (args.options.human_output()) {
    std::cout << summary << "\nWritten: ";
    for (std::size_t i = 0; i < written.size(); ++i)
      std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
  return kExitOk;
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<SweepArguments>();
  auto* command = app.add_subcommand(
      "sweep", "what-if analysis: the design check over a grid of case values, in this process");
  command->add_option("case", args->case_file, "case file (TOML), e.g. cases/pilot_hopper.toml")
      ->required()
      ->type_name("CASE");
  command
      ->add_option("--vary", args->vary,
                   "a case key and its values (repeatable; several make a grid): "
                   "hopper.semi_angle=15..40deg/5deg (step), hopper.outlet_width=20..100mm:9 "
                   "(count), :5log (log spacing), \"hopper.fill_height=0.2,0.3,0.5 m\" (list), "
                   "material=loblolly_pine,NAME (words)")
      ->required()
      ->type_name("KEY=RANGE")
      ->take_all()
      ->allow_extra_args(false);
  command->add_option("--set", args->options.sets, "a case value every point takes (repeatable)")
      ->type_name("KEY=VALUE")
      ->take_all()
      ->allow_extra_args(false);
  command
      ->add_option("--model", args->models,
                   "select an alternative model (repeatable), as for design")
      ->type_name("KEY=NAME")
      ->take_all()
      ->allow_extra_args(false);
  command->add_option("--out", args->options.out, "output folder (default out/<case name>_sweep)")
      ->type_name("DIR");
  add_json_option(*command, args->options, "sweep.json");
  add_verbosity_options(*command, args->options, true);
  command->callback([args, &exit_code] { exit_code = run_sweep(*args); });
}

}  // namespace feedflow
