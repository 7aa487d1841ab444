#pragma once
// `--rung L2|L3`: every point of a sweep as a full simulation of the case with the point's
// values (CEL-FEM for L2, DEM for L3); `--verify MODE`: every point's design check verified on a
// full rung as `design --verify` does it (escalating where its decision is inside its band).
// Each point has its own folder below the sweep's (points/p0007/: the simulation's files or the
// verification's runs, and run.json), the points shared among the ranks of a team
// (longest expected first) with each rank running its scene on its own threads. A point saved
// by an earlier run of the same sweep (same command line for the point, same case and material
// text) is read back, not run: a sweep that was stopped or killed goes on where it stopped.
#include <filesystem>
#include <optional>

#include "designer/simulate/simulation_request.hpp"
#include "designer/sweep/rank_team.hpp"
#include "designer/sweep/sweep_point.hpp"
#include "designer/verify/design_verification.hpp"
#include "fullsim/common/progress_sink.hpp"

namespace feedflow {

struct FullRungSweep {
  // --verify: the mode, budget and tolerances as typed (case, sets and runs are the point's);
  // none: each point is one simulation with `solver`.
  std::optional<VerificationRequest> verify;
  std::vector<std::string> models;  // --model KEY=NAME as typed (part of a point's identity)
  Solver solver = Solver::cel;
  std::optional<double> time;    // [s] simulated time of each point (--time); none: the scene's
  std::filesystem::path folder;  // the sweep's output folder
};

// The folder of point n below the sweep's folder.
std::filesystem::path point_folder(const std::filesystem::path& sweep_folder, std::size_t n);

// A point's run time relative to the other points of the sweep, from what the varied keys are
// known to do to it (finer cells, shorter steps, deeper slabs, more fill and longer runs cost
// more); 1 for keys with no known effect.
double expected_cost(const SweepRequest& request, const std::vector<std::size_t>& index);

struct FullRungOutcome {
  std::vector<SweepPoint> points;       // at rank 0: every point, in sweep order; elsewhere empty
  std::size_t made = 0, read_back = 0;  // over all ranks
  bool interrupted = false;             // some rank was stopped (Ctrl-C): run again to go on
};

// Runs (or reads back) every point, shared among the team; the points come back at rank 0.
// `solved` (a solve with --verify): the reduced solves of every point, each verified at its
// answer (a point whose target was not met in the range is not run and keeps its solve).
FullRungOutcome run_full_rung(const SweepRequest& request, const FullRungSweep& sweep,
                              const RankTeam& team, ProgressSink& progress,
                              const std::vector<SweepPoint>* solved = nullptr);

}  // namespace feedflow
