#pragma once
// Verifying a wedge hopper's discharge rate (and, from the same runs, its flow pattern) on the
// continuum rung (L2), for `design --verify`:
// CEL runs at fixed numbers of cells across the half outlet, extrapolated by Richardson. The plan
// is the cheapest that meets the tolerance within the budget, both read from the shipped bench
// table (the pilot hopper measured at 3, 6 and 12 cells across; wall time scaled by the outlet,
// t ~ W^-3 at fixed cells across). The verified rate then stands in the record as the rate (rung
// L2), the reduced one beside it, and the verdict is judged again on it.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "designer/bench/bench_table.hpp"
#include "designer/case/case.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

struct RateVerificationPlan {
  std::vector<double> cells_across;   // CEL levels; empty when no plan meets the tolerance in the budget
  double expected_error = 0.0;        // relative error bar the plan gave on the pilot hopper
  double estimated_seconds = 0.0;     // on the machine the bench table was measured on
  std::string description;            // the plan in words, or why there is none
};

// The cheapest of two levels (3, 6 cells; Richardson with the measured order, safety 3) and
// three levels (3, 6, 12; observed order, safety 1.25) whose measured error bar is at most
// `tolerance` and whose estimated time fits `budget_seconds`.
RateVerificationPlan plan_rate_verification(const Hopper& hopper, double tolerance, double budget_seconds);

struct RateVerification {
  BenchReference reference;   // the CEL estimate (value, error bar, source)
  std::string flow_pattern;   // the finest level's ("mass", "funnel"); empty when it has none
  std::string flow_pattern_model;
  std::string status = "done";  // or why there is no estimate
  double wall_seconds = 0.0;
  std::filesystem::path finest_run;  // the folder of the finest level's run (its snapshots)
};

// Runs the plan's levels on the case (`sets`: the user's --set overrides, as typed) below
// `runs_folder` (runs already there are read back); `progress` gets a line per run.
RateVerification verify_rate(const std::string& case_file, const std::vector<std::string>& sets, const Hopper& hopper,
                             const RateVerificationPlan& plan, const std::filesystem::path& runs_folder,
                             std::ostream* progress);

// The record with the verified rate: mass_flow_rate becomes the CEL estimate (rung L2),
// mass_flow_rate_reduced_model keeps the reduced one, the verdict is judged again and a note
// says "verified" (the reduced band and the CEL interval overlap) or "contradicted" with the numbers.
// The same runs show the flow pattern (wall-to-centre speed ratio of the finest level): on a
// wedge it stands beside the reduced one the same way; on a cone it is shown beside the reduced
// one (flow_pattern_continuum), which stays: the axisymmetric grid's reading does not converge.
void apply_rate_verification(const Case& c, const RateVerification& v, DesignRecord& record);

}  // namespace feedflow
