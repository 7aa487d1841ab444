#pragma once
// Runs of an arching verification laid down as it keeps them (designer/verify: one bench run per
// outlet width below its runs folder), so a test reads them back without a DEM step.
#include <filesystem>
#include <string>

#include "designer/bench/bench_run.hpp"

namespace feedflow::testing {

// The run the verification makes at outlet `width` ("48mm") of the case `q` with the point's
// settings `p.sets` (its case file relative to the source tree), saved as it saves it.
inline void lay_down_run(const BenchQuestion& q, const BenchPoint& p,
                         const std::filesystem::path& runs, const std::string& width,
                         const std::string& arching, double wall_seconds,
                         const std::string& commit) {
  BenchQuestion at = q;
  at.id = "verify_arching";
  at.case_file =
      (std::filesystem::path(FEEDFLOW_SOURCE_DIR) / q.case_file).lexically_normal().string();
  at.sets.insert(at.sets.end(), p.sets.begin(), p.sets.end());
  at.sets.push_back("hopper.outlet_width=" + width);
  BenchPoint dem;
  dem.setting = "DEM";
  dem.rung = "L3";
  dem.quantity = "arching";
  dem.solver = Solver::dem;
  BenchRun run;
  run.invocation = bench_invocation(at, dem);
  run.inputs = bench_inputs_fingerprint(at, dem, ".");
  run.wall_seconds = wall_seconds;
  run.commit = commit;
  run.results = {{"arching", {{"value", arching}}}};
  save_bench_run(bench_run_folder(runs, at, dem), run);
}

}  // namespace feedflow::testing
