// feedflow simulate <case> [--solver dem|cel] [--time 2s] [--out DIR] [--restart FILE] [--report]:
// verifies a case with a full simulation and writes results.json (rung L3 or L2),
// results.txt, timeseries.csv, the solver's snapshots and checkpoints, and the report.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <unistd.h>

#include "designer/case/case_loader.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/cli/output_folder.hpp"
#include "designer/cli/report_files.hpp"
#include "designer/design/case_inputs.hpp"
#include "designer/simulate/simulation.hpp"
#include "designer/simulate/simulation_pictures.hpp"
#include "designer/simulate/solver_choice.hpp"
#include "designer/sweep/rank_team.hpp"
#include "models/core/errors.hpp"
#include "models/os/atomic_file.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/quantity_parser.hpp"
#include "reports/results_json.hpp"
#include "reports/text_summary.hpp"
#include "reports/time_series_csv.hpp"

namespace feedflow {
namespace {

struct SimulateArguments {
  std::string case_file;
  CommandOptions options;
  std::string solver;   // empty: chosen by the seed's rule
  std::string time;     // "2 s"; empty: the scene's own end
  std::string restart;  // checkpoint file
  std::string checkpoint_every = "30 min";  // wall time between checkpoints on the way; 0: none
  bool report = false;
};

int run_simulate(const SimulateArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  // Under a launcher with several ranks a DEM run is shared among them: each runs the scene on
  // its part of the particles, the first writes the files and the log.
  const RankTeam& team = RankTeam::world();
  std::vector<SetOverride> overrides;
  for (const auto& s : args.options.sets) overrides.push_back(parse_set_override(s));
  std::optional<Solver> asked;
  if (!args.solver.empty()) asked = parse_solver(args.solver);
  std::optional<double> end_time;
  if (!args.time.empty()) {
    try {
      end_time = parse_quantity_as(args.time, dim::time, false);
    } catch (const UnitError& e) {
      throw InputError("--time", "", e.what());
    }
    if (!(*end_time > 0.0)) throw InputError("--time", "", "the simulated time must be > 0 s, e.g. 2 s");
  }
  double checkpoint_every = 0.0;
  try {
    checkpoint_every = parse_quantity_as(args.checkpoint_every, dim::time, false);
  } catch (const UnitError& e) {
    throw InputError("--checkpoint-every", "", e.what());
  }
  if (!(checkpoint_every >= 0.0))
    throw InputError("--checkpoint-every", "",
                     "expected a wall time >= 0 s, e.g. 30 min (0 s: no checkpoint on the way)");
  if (!args.restart.empty() && !std::filesystem::is_regular_file(args.restart))
    throw InputError("--restart", "", "no such checkpoint file: " + args.restart);

  const Case c = load_case(args.case_file, overrides);
  if (!args.options.quiet)
    for (const auto& w : c.warnings) std::cerr << "feedflow: warning: " << w << '\n';
  const SolverChoice choice = choose_solver(c, asked);
  if (team.size() > 1 && choice.solver != Solver::dem)
    throw InputError("mpirun", "",
                     "the CEL-FEM solver runs in one process (a DEM run is shared among MPI "
                     "ranks): run it without mpirun; under mpirun, `feedflow sweep --rung L2` "
                     "shares whole runs among the ranks");

  SimulationRequest request;
  request.case_data = c;
  request.solver = choice.solver;
  request.end_time = end_time;
  // A run writes its snapshots and checkpoint as it goes: it needs a folder even with --json -.
  request.out = *output_folder(args.options, c.name, std::string("_") + to_string(choice.solver), true);
  request.restart = args.restart;
  request.checkpoint_every = checkpoint_every;
  request.progress = team.root() && !args.options.quiet && isatty(STDERR_FILENO);
  request.log = team.root() && args.options.human_output() ? &std::cout : nullptr;
  if (request.log) std::cout << std::unitbuf;  // a run logged to a file shows its phases as they come
  if (team.size() > 1) request.ranks = DemRanks::world();
  // Created and locked until the run ends, by the first rank; the others stop with it when
  // it cannot.
  std::optional<OutputFolder> folder;
  std::optional<InputError> unclaimed;
  if (team.root()) try {
      folder.emplace(request.out, "--out");
    } catch (const InputError& e) {
      unclaimed = e;
    }
  const bool claimed = team.broadcast(unclaimed ? 0 : 1) != 0;  // the first rank's
  if (unclaimed) throw *unclaimed;
  if (!claimed) throw InputError("--out", "", "the first rank could not claim the output folder");
  if (request.log) {
    *request.log << "feedflow simulate: " << choice.reason << '\n';
    if (team.size() > 1)
      *request.log << "feedflow simulate: the DEM run shared among " << team.size() << " MPI ranks\n";
  }

  install_interrupt_handler();
  SimulationOutcome outcome;
  try {
    outcome = simulate(request);
  } catch (...) {
    if (folder) folder->discard_if_unused();  // a run that failed before writing anything leaves no folder
    throw;
  }
  if (!team.root()) return verdict_exit_code(args.options, outcome.record.verdict.status);
  DesignRecord& record = outcome.record;
  describe_case(c, record);
  record.assumptions.insert(record.assumptions.begin(), choice.reason);
  record.command_line = invocation();
  record.simulation_runs = {"."};  // the snapshots are beside the results
  record.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string summary = text_summary(record);
  const std::string json = to_json(record).dump(2) + "\n";
  auto files = results_files(request.out, json, summary, args.options);
  if (!outcome.series.empty()) files.push_back({request.out / "timeseries.csv", to_csv(outcome.series), "--out"});
  if (args.report)
    for (auto& file :
         report_files(request.out, record, record_pictures(record, request.out, std::cerr)))
      files.push_back(std::move(file));
  auto written = write_outputs(files, args.options.json_to_stdout() ? &json : nullptr, args.options.verbose,
                               &*folder);
  for (auto& f : outcome.files) written.push_back(std::move(f));

  if (args.options.human_output()) {
    std::cout << summary << "\nWritten: ";
    for (std::size_t i = 0; i < written.size(); ++i)
      std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
  if (outcome.end == SimulationEnd::interrupted) {
    bool checkpointed = false;
    for (const auto& f : written) checkpointed = checkpointed || f.filename() == "checkpoint.h5";
    std::cerr << (checkpointed ? "feedflow: interrupted; continue with --restart and the checkpoint listed above\n"
                               : "feedflow: interrupted before a checkpoint could be written (before "
                                 "the fill's first batch was in); run again\n");
    return kExitInterrupted;
  }
  return verdict_exit_code(args.options, record.verdict.status);
}

}  // namespace

void add_simulate_command(Command& program, int& exit_code) {
  auto args = std::make_shared<SimulateArguments>();
  auto command = program.subcommand(
      "simulate", "verify a case with a full simulation: particles (DEM) or continuum (CEL-FEM)");
  command.option("case", args->case_file, "case file (TOML), e.g. cases/rotating_drum_20rpm.toml")
      .required()
      .type_name("CASE");
  command
      .option("--solver", args->solver,
              "dem (particles, rung L3) or cel (CEL-FEM continuum, rung L2); default: "
              "the seed's rule (continuum for hoppers and chutes, particles for drums)")
      .type_name("NAME");
  command
      .option("--time", args->time,
              "simulated time after filling, with its unit (e.g. 2s); default: until the "
              "measured quantity has converged or the flow has stopped")
      .type_name("TIME");
  command.option("--restart", args->restart, "continue the run saved in this checkpoint")
      .type_name("FILE");
  command
      .option(
          "--checkpoint-every", args->checkpoint_every,
          "wall time between the checkpoints a run writes on the way (OUT/checkpoint.h5; after "
          "a DEM fill), so that a run killed outright continues with --restart; 0 s: only at the "
          "end or on Ctrl-C")
      .show_default()
      .type_name("TIME");
  add_case_options(command, args->options, "out/<case name>_<solver>, e.g. out/pilot_hopper_cel");
  command.flag("--report", args->report,
               "also write report.pdf and report.html, with pictures of the simulation");
  command.on_run([args, &exit_code] {
    // A run shared among ranks fails on every rank alike: the first says why.
    try {
      exit_code = run_simulate(*args);
    } catch (const InputError&) {
      if (RankTeam::world().root()) throw;
      exit_code = kExitBadInput;
    } catch (const NumericalFailure&) {
      if (RankTeam::world().root()) throw;
      exit_code = kExitNumericalFailure;
    }
  });
}

}  // namespace feedflow
