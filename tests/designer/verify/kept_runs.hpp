#pragma once
// Runs of an arching or a stopping verification laid down as they keep them (designer/verify: one
// bench run per outlet width or layer thickness below its runs folder), so a test reads them back
// without a DEM step.
#include <filesystem>
#include <string>
#include <vector>

#include "designer/bench/bench_run.hpp"
#include "designer/verify/arching_verification.hpp"
#include "designer/verify/stopping_verification.hpp"

namespace feedflow::testing {

// The run an arching verification of `case_file` (as its command names it, found below
// `source_root`) with `sets` makes at outlet `width` [m], saved below `runs` as it saves it.
inline void lay_down_run(const std::string& case_file, const std::vector<std::string>& sets,
                         const std::filesystem::path& source_root,
                         const std::filesystem::path& runs, double width,
                         const std::string& arching, double wall_seconds, const std::string& commit,
                         const nlohmann::ordered_json& more = {}) {
  const BenchQuestion at = arching_run_question(case_file, sets, width);
  BenchRun run;
  run.invocation = bench_invocation(at, arching_run_point());
  run.inputs = bench_inputs_fingerprint(at, arching_run_point(), source_root);
  run.wall_seconds = wall_seconds;
  run.commit = commit;
  run.results = {{"arching", {{"value", arching}}}};
  for (const auto& [key, value] : more.items()) run.results[key] = value;
  save_bench_run(bench_run_folder(runs, at, arching_run_point()), run);
}

// The same for the case `q` (relative to the source tree) with the point's settings `p.sets`, as
// a bench point's verification names it.
inline void lay_down_run(const BenchQuestion& q, const BenchPoint& p,
                         const std::filesystem::path& runs, double width,
                         const std::string& arching, double wall_seconds, const std::string& commit,
                         const nlohmann::ordered_json& more = {}) {
  std::vector<std::string> sets = q.sets;
  sets.insert(sets.end(), p.sets.begin(), p.sets.end());
  lay_down_run(
      (std::filesystem::path(FEEDFLOW_SOURCE_DIR) / q.case_file).lexically_normal().string(), sets,
      ".", runs, width, arching, wall_seconds, commit, more);
}

// The layer a stopping verification of `case_file` (as its command names it) with `sets` makes at
// `thickness` [m], saved below `runs` as it saves it: `state` "at rest" or "flowing", the
// thickness it measured at its end `measured` [m].
inline void lay_down_layer(const std::string& case_file, const std::vector<std::string>& sets,
                           const std::filesystem::path& runs, double thickness,
                           const std::string& state, double measured, double wall_seconds) {
  const BenchQuestion at = layer_run_question(case_file, sets, thickness);
  BenchRun run;
  run.invocation = bench_invocation(at, layer_run_point());
  run.inputs = bench_inputs_fingerprint(at, layer_run_point(), ".");
  run.wall_seconds = wall_seconds;
  run.commit = "aaaa";
  run.results = {{"layer_state", {{"value", state}}},
                 {"layer_thickness", {{"value", measured}, {"unit", "m"}}}};
  save_bench_run(bench_run_folder(runs, at, layer_run_point()), run);
}

}  // namespace feedflow::testing
