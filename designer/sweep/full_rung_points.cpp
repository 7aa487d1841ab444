#include "designer/sweep/full_rung_points.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "designer/bench/bench_run.hpp"
#include "designer/design/design_check.hpp"
#include "designer/sweep/point_queue.hpp"
#include "designer/sweep/sweep_grid.hpp"
#include "models/core/commit.hpp"
#include "models/os/interrupt_request.hpp"
#include "reports/results_json.hpp"

namespace feedflow {
namespace {

// The point as the bench runs a point: the case with the fixed values is the question, the
// point's own values and the solver are the setting.
BenchQuestion question_of(const SweepRequest& request) {
  BenchQuestion q;
  q.id = "sweep";
  q.case_file = request.parsed.path;
  for (const auto& s : request.fixed) q.sets.push_back(s.key + "=" + s.value);
  return q;
}

BenchPoint bench_point_of(const SweepRequest& request, const FullRungSweep& sweep,
                          const std::vector<std::size_t>& index) {
  BenchPoint p;
  if (!sweep.verify) {
    p.solver = sweep.solver;
    p.rung = sweep.solver == Solver::cel ? "L2" : "L3";
    p.time = sweep.time;
  }
  p.models = sweep.models;
  for (std::size_t k = 0; k < request.axes.size(); ++k)
    p.sets.push_back(request.axes[k].case_key + "=" + request.axes[k].values[index[k]].text);
  return p;
}

// A verified point: the design check, verified in the point's folder, saved there as a run.
BenchRun verified_point(const SweepRequest& request, const FullRungSweep& sweep,
                        const BenchQuestion& question, const BenchPoint& point,
                        const std::filesystem::path& folder, bool& made) {
  const VerificationRequest& v = *sweep.verify;
  const std::string invocation =
      bench_invocation(question, point) + " --verify " + v.mode + " --tolerance " + v.tolerance +
      " --budget " + v.budget + " --width-tolerance " + v.width_tolerance +
      (v.thickness_tolerance.empty() ? std::string()
                                     : " --thickness-tolerance " + v.thickness_tolerance);
  const std::string inputs = bench_inputs_fingerprint(question, point, "");
  made = false;
  if (auto saved = saved_bench_run(folder, invocation, inputs, false)) return std::move(*saved);
  made = true;
  BenchRun run;
  run.invocation = invocation;
  run.inputs = inputs;
  run.commit = kCommit;
  run.cores = omp_get_max_threads();
  const auto start = std::chrono::steady_clock::now();
  try {
    VerificationRequest asked = v;
    asked.case_file = question.case_file;
    asked.sets = question.sets;
    asked.sets.insert(asked.sets.end(), point.sets.begin(), point.sets.end());
    asked.runs = folder / "runs";
    asked.log = nullptr;
    std::vector<SetOverride> overrides;
    for (const auto& s : asked.sets) overrides.push_back(parse_set_override(s));
    const Case c = load_case(request.parsed, overrides, request.materials);
    DesignRecord record = design_check(c, request.models);
    if (!verify_design(asked, c, record)) run.status = "interrupted";
    const auto saved = to_json(record);
    run.results = saved.at("results");
    run.verdict = saved.at("verdict");
  } catch (const std::exception& e) {  // the point says why; the sweep goes on
    run.status = std::string("failed: ") + e.what();
  }
  run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (run.status != "interrupted") save_bench_run(folder, run);
  return run;
}

SweepPoint point_of_run(const BenchRun& run, const std::string& rung) {
  SweepPoint p;
  p.rung = rung;
  p.wall_seconds = run.wall_seconds;
  p.done = run.done();
  if (!p.done) {
    p.error = run.status;
    return p;
  }
  p.results = estimates_from_json(run.results);
  Rung highest = Rung::L0;  // a verified point stands on the highest rung it reached
  for (auto& [key, e] : p.results) {
    e.model.clear();
    highest = std::max(highest, e.rung);
  }
  if (rung.empty()) p.rung = to_string(highest);
  if (run.verdict.is_object()) {
    p.verdict = verdict_status_from_string(run.verdict.value("status", "unknown"));
    for (const auto& f : run.verdict.value("findings", nlohmann::ordered_json::array()))
      if (f.value("status", "") == to_string(p.verdict) && !f.value("quantity", "").empty()) {
        if (p.governing.empty()) p.governing_reason = f.value("text", "");
        p.governing.push_back(f.value("quantity", ""));
      }
  }
  return p;
}

// How each known key scales the run time: cost ~ value^power.
double cost_power(const std::string& key) {
  if (key == "cel.cell_size") return -3.0;  // cells ~ h^-2, steps ~ h^-1
  if (key == "dem.time_step" || key == "dem.force_time_step") return -1.0;
  if (key == "dem.slab_depth" || key == "hopper.fill_height" || key == "chute.length" ||
      key == "cel.end_time" || key == "dem.end_time")
    return 1.0;
  if (key == "drum.diameter") return 2.0;
  if (key == "material.particle_diameter") return -3.0;
  return 0.0;
}

// A solved point's answer, where it has one.
const SweepSolution* answered(const std::vector<SweepPoint>* solved, std::size_t point) {
  if (!solved || !(*solved)[point].solution) return nullptr;
  const SweepSolution& s = *(*solved)[point].solution;
  return s.outcome == SweepSolution::Outcome::solved ? &s : nullptr;
}

}  // namespace

std::filesystem::path point_folder(const std::filesystem::path& sweep_folder, std::size_t n) {
  char name[24];
  std::snprintf(name, sizeof name, "p%04zu", n);
  return sweep_folder / "points" / name;
}

double expected_cost(const SweepRequest& request, const std::vector<std::size_t>& index) {
  double cost = 1.0;
  for (std::size_t k = 0; k < request.axes.size(); ++k) {
    const SweepAxis& a = request.axes[k];
    const double power = cost_power(a.case_key);
    const auto& v = a.values[index[k]];
    if (power != 0.0 && v.si && *v.si > 0.0) cost *= std::pow(*v.si, power);
  }
  return cost;
}

FullRungOutcome run_full_rung(const SweepRequest& request, const FullRungSweep& sweep,
                              const RankTeam& team, ProgressSink& progress,
                              const std::vector<SweepPoint>* solved) {
  const std::size_t n = point_count(request);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::vector<double> cost(n);
  for (std::size_t i = 0; i < n; ++i) cost[i] = expected_cost(request, point_index(request, i));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });

  const BenchQuestion question = question_of(request);
  const std::string rung = sweep.verify ? "" : sweep.solver == Solver::cel ? "L2" : "L3";
  nlohmann::ordered_json mine = nlohmann::ordered_json::object();  // point number -> run
  long long made = 0, read_back = 0, interrupted = 0;
  if (team.root()) progress.begin("sweep", static_cast<double>(n), "points started");
  {
    PointQueue queue(team, n);
    while (const auto position = queue.next()) {
      const std::size_t point = order[*position];
      if (team.root()) progress.update(static_cast<double>(queue.handed_out()));
      if (solved && !answered(solved, point)) continue;  // nothing to verify: keeps its solve
      BenchPoint p = bench_point_of(request, sweep, point_index(request, point));
      if (const SweepSolution* s = answered(solved, point))
        p.sets.push_back(request.solve->axis.case_key + "=" + s->text);
      bool was_made = true;
      const auto folder = point_folder(sweep.folder, point);
      BenchRun run;
      try {  // a rank must not leave the team over one point (a full disk): the others wait
        run = sweep.verify ? verified_point(request, sweep, question, p, folder, was_made)
                           : run_or_read_back(question, p, "", folder, was_made);
      } catch (const std::exception& e) {
        run.status = std::string("failed: ") + e.what();
      }
      (was_made ? made : read_back) += 1;
      mine[std::to_string(point)] = bench_run_json(run);
      if (run.status == "interrupted" || interrupt_requested()) {
        interrupted = 1;
        queue.stop();
        break;
      }
    }
  }
  if (team.root()) progress.finish();

  FullRungOutcome outcome;
  const nlohmann::ordered_json counts = {made, read_back, interrupted};
  const auto texts = team.gather(mine.dump() + "\n" + counts.dump());
  if (!team.root()) return outcome;
  outcome.points.resize(n);
  std::vector<bool> seen(n, false);
  for (const auto& text : texts) {
    const auto split = text.rfind('\n');
    const auto runs = nlohmann::ordered_json::parse(text.substr(0, split));
    const auto c = nlohmann::ordered_json::parse(text.substr(split + 1));
    outcome.made += c.at(0).get<std::size_t>();
    outcome.read_back += c.at(1).get<std::size_t>();
    outcome.interrupted = outcome.interrupted || c.at(2).get<int>() != 0;
    for (const auto& [number, run] : runs.items()) {
      const std::size_t i = std::stoul(number);
      outcome.points[i] = point_of_run(bench_run_from_json(run), rung);
      outcome.points[i].folder = point_folder("", i);  // relative to the sweep's folder
      seen[i] = true;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (solved) {  // the solve, with the verification's answers at its value when there is one
      if (!answered(solved, i)) {
        outcome.points[i] = (*solved)[i];
        continue;
      }
      outcome.points[i].solution = (*solved)[i].solution;
    }
    outcome.points[i].index = point_index(request, i);
    if (!seen[i]) {
      outcome.points[i].rung = rung.empty() ? "L0" : rung;
      outcome.points[i].error = "not run (the sweep was interrupted)";
    }
  }
  return outcome;
}

}  // namespace feedflow
