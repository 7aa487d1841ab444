// feedflow sweep <case> --vary KEY=RANGE ...: what-if analysis on the reduced rungs, every point
// answered in this process (designer/sweep/).
#include <algorithm>
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
#include "designer/cli/report_files.hpp"
#include "designer/design/design_check.hpp"
#include "designer/sweep/full_rung_points.hpp"
#include "designer/sweep/rank_team.hpp"
#include "designer/sweep/sweep_output.hpp"
#include "designer/sweep/sweep_report.hpp"
#include "designer/sweep/sweep_sample.hpp"
#include "designer/sweep/sweep_solve.hpp"
#include "fullsim/common/progress_line.hpp"
#include "models/core/errors.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

struct SweepArguments {
  std::string case_file;
  std::vector<std::string> vary;
  std::vector<std::string> models;
  std::string solve_for, target, solve_tolerance, sample, rung, time;
  VerificationRequest verify;  // --verify, --budget, --tolerance, --width-/--thickness-tolerance
  bool report = false;
  CommandOptions options;
};

// --solve-for KEY[=RANGE] --target CONDITION [--solve-tolerance VALUE]: the solved key taken out
// of the grid (its range from --vary when not given here), the target checked against the case.
SweepSolve solve_request(const SweepArguments& args, SweepRequest& request, const Case& base) {
  SweepSolve solve;
  if (args.solve_for.find('=') != std::string::npos) {
    solve.axis = parse_sweep_axis(args.solve_for, "--solve-for");
  } else {
    const auto it = std::find_if(request.axes.begin(), request.axes.end(), [&](const auto& a) {
      return a.key == args.solve_for || a.case_key == args.solve_for;
    });
    if (it == request.axes.end())
      throw InputError(
          "--solve-for", args.solve_for,
          "give the range to search, --solve-for " + args.solve_for +
              "=RANGE (e.g. hopper.outlet_width=20..200mm:10), or vary it with --vary");
    solve.axis = *it;
    request.axes.erase(it);
  }
  for (const auto& a : request.axes)
    if (a.case_key == solve.axis.case_key)
      throw InputError("--solve-for", args.solve_for, solve.axis.key + " is also varied");
  if (!solve.axis.numeric() || solve.axis.values.size() < 2)
    throw InputError("--solve-for", args.solve_for,
                     "solves for a number over a range of at least two values");
  if (args.target.empty())
    throw InputError("--target", "",
                     "--solve-for needs a target: pass, not-fail, RESULT>=VALUE or RESULT=WORD");
  solve.target = parse_sweep_target(args.target);
  // The target's result, kind and unit, checked on the case itself.
  check_sweep_target(solve.target,
                     design_check(base, request.models, DesignDetail::results).results);
  solve.tolerance = default_solve_tolerance(solve.axis);
  if (!args.solve_tolerance.empty()) {
    const CaseKeyKind kind = case_key_kind(solve.axis.case_key);
    try {
      solve.tolerance = parse_quantity_as(args.solve_tolerance, kind.dimension, false);
    } catch (const UnitError& e) {
      throw InputError("--solve-tolerance", args.solve_tolerance, e.what());
    }
    if (!(solve.tolerance > 0.0))
      throw InputError("--solve-tolerance", args.solve_tolerance, "must be positive");
  }
  return solve;
}

// The request from the command line: axes, fixed values, models, the case parsed once, the
// solve and the sample. Returns the case with the fixed values (its faults named as design
// names them).
Case build_request(const SweepArguments& args, SweepRequest& request) {
  for (const auto& v : args.vary) request.axes.push_back(parse_sweep_axis(v));
  for (std::size_t a = 0; a < request.axes.size(); ++a)
    for (std::size_t b = 0; b < a; ++b)
      if (request.axes[a].case_key == request.axes[b].case_key)
        throw InputError("--vary", args.vary[a], request.axes[a].key + " is varied twice");
  constexpr double kMaxPoints = 10e6;
  double points = 1.0;
  for (const auto& a : request.axes) points *= static_cast<double>(a.values.size());
  if (args.sample.empty() && points > kMaxPoints)
    throw InputError("--vary", args.vary.back(),
                     "the grid has " + std::to_string(static_cast<long long>(points)) +
                         " points, more than 10 million: use coarser ranges");
  for (const auto& s : args.options.sets) request.fixed.push_back(parse_set_override(s));
  request.models = ModelChoices::parse(args.models);
  request.parsed = parse_case(args.case_file);
  const std::filesystem::path folder = std::filesystem::path(args.case_file).parent_path();
  request.materials =
      MaterialLibrary::standard(folder.empty() ? std::filesystem::path(".") : folder);
  Case base = load_case(request.parsed, request.fixed, request.materials);
  if (!args.solve_for.empty())
    request.solve = solve_request(args, request, base);
  else if (!args.target.empty())
    throw InputError("--target", args.target, "a target needs --solve-for KEY");
  if (request.axes.empty() && !request.solve)
    throw InputError("--vary", "", "give what to vary: --vary KEY=RANGE (repeatable)");
  if (!args.sample.empty()) {
    const SampleRequest sample = parse_sample(args.sample);
    if (request.axes.empty())
      throw InputError("--sample", args.sample, "samples the --vary axes: give at least one");
    request.axes = latin_hypercube(request.axes, sample);
    request.sampled = true;
  }
  return base;
}

// --rung: none for the reduced rungs (L0, L1: the design check), else the solver of L2 or L3.
std::optional<Solver> full_rung_solver(const std::string& rung) {
  if (rung.empty() || rung == "L0" || rung == "L1") return std::nullopt;
  if (rung == "L2") return Solver::cel;
  if (rung == "L3") return Solver::dem;
  throw InputError("--rung", rung,
                   "expected L0 or L1 (the design check), L2 (CEL-FEM) or L3 (DEM)");
}

std::optional<double> simulated_time(const std::string& text) {
  if (text.empty()) return std::nullopt;
  double t = 0.0;
  try {
    t = parse_quantity_as(text, dim::time, false);
  } catch (const UnitError& e) {
    throw InputError("--time", text, e.what());
  }
  if (!(t > 0.0)) throw InputError("--time", text, "the simulated time must be > 0 s, e.g. 2 s");
  return t;
}

// sweep.json, sweep.csv, sweep.txt (and the --json copy) written all or none.
void write_sweep(const SweepArguments& args, const SweepRequest& request, const Case& base,
                 const std::vector<SweepPoint>& answered, const SweepTiming& timing,
                 const std::filesystem::path& out, OutputFolder& claimed) {
  const std::string json = sweep_json(request, answered, timing, invocation());
  const std::string summary = sweep_summary(request, answered, timing);
  std::vector<OutputFile> files{{out / "sweep.json", json, "--out"},
                                {out / "sweep.csv", sweep_csv(request, answered), "--out"},
                                {out / "sweep.txt", summary, "--out"}};
  if (!args.options.json.empty() && !args.options.json_to_stdout())
    files.push_back({args.options.json, json, "--json"});
  if (args.report)
    for (auto& f : report_files(out, sweep_record(request, base, answered, timing, invocation())))
      files.push_back(std::move(f));
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json : nullptr,
                                     args.options.verbose, &claimed);
  if (args.options.human_output()) {
    std::cout << summary << "\nWritten: ";
    for (std::size_t i = 0; i < written.size(); ++i)
      std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The points on the reduced rungs, in this process, on its threads.
int run_reduced(const SweepArguments& args, const SweepRequest& request, const Case& base,
                std::chrono::steady_clock::time_point start) {
  TerminalProgress progress = TerminalProgress::for_terminal(!args.options.human_output());
  const auto points_start = std::chrono::steady_clock::now();
  const std::vector<SweepPoint> answered = run_grid(request, progress);
  SweepTiming timing;
  timing.point_seconds = seconds_since(points_start);
  std::size_t refused = 0, never_met = 0;
  for (const auto& p : answered) {
    refused += !p.done;
    never_met += p.solution && p.solution->outcome == SweepSolution::Outcome::never_met;
  }
  if (never_met == answered.size())
    throw InputError("--target", args.target,
                     "the range cannot meet it: " + answered.front().error);
  if (refused == answered.size())
    throw InputError(request.solve ? "--solve-for" : "--vary",
                     request.solve ? args.solve_for : args.vary.front(),
                     "no point of the sweep could be checked; the first: " +
                         answered.front().error);
  timing.threads = omp_get_max_threads();
  timing.wall_seconds = seconds_since(start);
  const auto out = output_folder(args.options, base.name, "_sweep", true);
  OutputFolder claimed(*out, "--out");
  write_sweep(args, request, base, answered, timing, *out, claimed);
  return kExitOk;
}

// The points as simulations, shared among the ranks of an MPI run (one rank without mpirun);
// the folder is claimed by rank 0 before any rank writes into it and kept between runs, so a
// stopped sweep goes on where it stopped.
int run_simulated(const SweepArguments& args, const SweepRequest& request, const Case& base,
                  FullRungSweep sweep, std::chrono::steady_clock::time_point start) {
  // A solve with --verify: every rank solves on the reduced rungs (the same answers, in
  // milliseconds), then the answers are verified as points.
  std::optional<std::vector<SweepPoint>> solved;
  if (request.solve) {
    SilentProgress quiet;
    solved = run_grid(request, quiet);
  }
  const RankTeam& team = RankTeam::world();
  const auto out = output_folder(args.options, base.name, "_sweep", true);
  std::optional<OutputFolder> claimed;
  std::optional<InputError> refusal;
  if (team.root()) try {
      claimed.emplace(*out, "--out");
    } catch (const InputError& e) {
      refusal = e;
    }
  if (!team.broadcast(refusal ? 0 : 1)) {
    if (refusal) throw *refusal;
    return kExitBadInput;  // rank 0 says why
  }
  install_interrupt_handler();
  if (team.root() && args.options.human_output())
    std::cout << "feedflow sweep: " << point_count(request) << " points "
              << (sweep.verify ? "verified (--verify " + sweep.verify->mode + ")"
                               : std::string("on ") + to_string(sweep.solver) +
                                     (sweep.solver == Solver::cel ? " (L2)" : " (L3)"))
              << ", " << team.size() << (team.size() == 1 ? " rank" : " ranks") << " x "
              << omp_get_max_threads() << (omp_get_max_threads() == 1 ? " thread" : " threads")
              << ", in " << out->string() << "/points\n";
  TerminalProgress progress =
      TerminalProgress::for_terminal(!(team.root() && args.options.human_output()));
  const auto points_start = std::chrono::steady_clock::now();
  sweep.folder = *out;
  const FullRungOutcome outcome =
      run_full_rung(request, sweep, team, progress, solved ? &*solved : nullptr);
  if (!team.root()) return outcome.interrupted ? kExitInterrupted : kExitOk;
  SweepTiming timing;
  timing.point_seconds = seconds_since(points_start);
  timing.threads = omp_get_max_threads();
  timing.ranks = team.size();
  timing.made = outcome.made;
  timing.read_back = outcome.read_back;
  timing.wall_seconds = seconds_since(start);
  write_sweep(args, request, base, outcome.points, timing, *out, *claimed);
  if (outcome.interrupted) {
    std::cerr << "feedflow: interrupted; run the same command again to go on (points done are "
                 "read back)\n";
    return kExitInterrupted;
  }
  return kExitOk;
}

int run_sweep(const SweepArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  const RankTeam& team = RankTeam::world();
  SweepRequest request;
  const Case base = build_request(args, request);
  const std::optional<Solver> solver = full_rung_solver(args.rung);
  const bool verify = args.verify.mode != "off";
  if (!solver && !args.time.empty())
    throw InputError("--time", args.time, "sets the simulated time of --rung L2 or L3 points");
  if (solver && verify)
    throw InputError("--verify", args.verify.mode,
                     "--rung " + args.rung +
                         " simulates every point already; --verify escalates the design check's "
                         "points where their decision needs it: give one of them");
  if (solver && request.solve)
    throw InputError("--solve-for", args.solve_for,
                     "solves on the reduced rungs (L0, L1) in this version, and --verify checks "
                     "each answer on a full rung; with --rung vary the key with --vary and read "
                     "the boundary off the points");
  if (team.root() && !args.options.quiet)
    for (const auto& w : base.warnings) std::cerr << "feedflow: warning: " << w << '\n';
  if (solver || verify) {
    FullRungSweep sweep;
    if (verify) sweep.verify = args.verify;
    if (solver) sweep.solver = *solver;
    sweep.time = simulated_time(args.time);
    sweep.models = args.models;
    return run_simulated(args, request, base, sweep, start);
  }
  // The reduced rungs answer thousands of points a second on rank 0's threads.
  return team.root() ? run_reduced(args, request, base, start) : kExitOk;
}

}  // namespace

void add_sweep_command(Command& program, int& exit_code) {
  auto args = std::make_shared<SweepArguments>();
  auto command = program.subcommand(
      "sweep",
      "what-if analysis: the design check over a grid, a sample or a solve, in this process; "
      "with --rung or --verify each point simulated, shared among MPI ranks");
  command.option("case", args->case_file, "case file (TOML), e.g. cases/pilot_hopper.toml")
      .required()
      .type_name("CASE");
  command
      .option("--vary", args->vary,
              "a case key and its values (repeatable; several make a grid): "
              "hopper.semi_angle=15..40deg/5deg (step), hopper.outlet_width=20..100mm:9 "
              "(count), :5log (log spacing), \"hopper.fill_height=0.2,0.3,0.5 m\" (list), "
              "material=loblolly_pine,NAME (words)")
      .type_name("KEY=RANGE")
      .repeatable();
  command
      .option("--solve-for", args->solve_for,
              "at each point of the --vary grid, the value of KEY that meets --target, by "
              "scanning its range (KEY=RANGE, or its --vary) and bisection")
      .type_name("KEY[=RANGE]");
  command
      .option("--target", args->target,
              "what --solve-for looks for: pass, not-fail, RESULT>=VALUE (e.g. "
              "mass_flow_rate>=5kg/s; >, <=, <, = its crossing; RESULT.low, RESULT.high), "
              "RESULT=WORD (flow_pattern=mass, regime!=rolling)")
      .type_name("CONDITION");
  command
      .option("--solve-tolerance", args->solve_tolerance,
              "the solved value's bracket width (default a thousandth of its range)")
      .type_name("VALUE");
  command
      .option("--sample", args->sample,
              "lhs:N[:SEED]: a Latin hypercube of N points over the --vary ranges instead "
              "of their grid (seeded: the same points every run)")
      .type_name("lhs:N");
  command
      .option("--rung", args->rung,
              "L0 (default: the design check, in this process), L2 (each point a CEL-FEM "
              "simulation) or L3 (DEM); simulated points are shared among the ranks of "
              "mpirun -np N, each in its own folder, and read back when the sweep is run "
              "again")
      .type_name("L0|L2|L3");
  command.option("--time", args->time, "simulated time of each --rung L2|L3 point, e.g. 2s")
      .type_name("TIME");
  command
      .option("--verify", args->verify.mode,
              "verify each point as design --verify does (auto: where its decision is inside "
              "its band; cel; dem), in its own folder, shared among MPI ranks like --rung")
      .show_default()
      .one_of({"off", "auto", "cel", "dem"})
      .type_name("RUNG");
  command.option("--budget", args->verify.budget, "wall time a point's verification may take")
      .show_default()
      .type_name("TIME");
  command
      .option("--tolerance", args->verify.tolerance, "error bar a point's verification must reach")
      .show_default()
      .type_name("FRACTION");
  command
      .option("--width-tolerance", args->verify.width_tolerance,
              "--verify dem: bracket of the bisection on the outlet width")
      .show_default()
      .type_name("WIDTH");
  command
      .option("--thickness-tolerance", args->verify.thickness_tolerance,
              "--verify dem on a chute: bracket of the bisection on the stopping layer's "
              "thickness (default one DEM sphere diameter)")
      .type_name("THICKNESS");
  command.option("--set", args->options.sets, "a case value every point takes (repeatable)")
      .type_name("KEY=VALUE")
      .repeatable();
  command.option("--model", args->models, "select an alternative model (repeatable), as for design")
      .type_name("KEY=NAME")
      .repeatable();
  command.flag("--report", args->report,
               "also write report.pdf and report.html: the table and the design charts");
  command.option("--out", args->options.out, "output folder (default out/<case name>_sweep)")
      .type_name("DIR");
  add_json_option(command, args->options, "sweep.json");
  add_verbosity_options(command, args->options, true);
  command.on_run([args, &exit_code] { exit_code = run_sweep(*args); });
}

}  // namespace feedflow
