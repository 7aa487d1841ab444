#pragma once
// Runs of an arching verification laid down as it keeps them (designer/verify: one bench run per
// outlet width below its runs folder), so a test reads them back without a DEM step.
#include <filesystem>
#include <string>

#include "designer/bench/bench_run.hpp"
#include "designer/verify/arching_verification.hpp"

namespace feedflow::testing {

// The run the verification makes at outlet `width` [m] of the case `q` with the point's settings
// `p.sets` (its case file relative to the source tree), saved as it saves it.
inline void lay_down_run(const BenchQuestion& q, const BenchPoint& p,
                         const std::filesystem::path& runs, double width,
                         const std::string& arching, double wall_seconds,
                         const std::string& commit) {
  std::vector<std::string> sets = q.sets;
  sets.insert(sets.end(), p.sets.begin(), p.sets.end());
  const BenchQuestion at = arching_run_question(
      (std::filesystem::path(FEEDFLOW_SOURCE_DIR) / q.case_file).lexically_normal().string(), sets,
      width);
  BenchRun run;
  run.invocation = bench_invocation(at, arching_run_point());
  run.inputs = bench_inputs_fingerprint(at, arching_run_point(), ".");
  run.wall_seconds = wall_seconds;
  run.commit = commit;
  run.results = {{"arching", {{"value", arching}}}};
  save_bench_run(bench_run_folder(runs, at, arching_run_point()), run);
}

}  // namespace feedflow::testing
