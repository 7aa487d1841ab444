// Verifying a drum's answers on a full rung (designer/verify/simulation_verification): the
// simulated angle is judged by its mean's interval, not by the 2 SD band of its snapshots.
#include <gtest/gtest.h>

#include "designer/case/case_loader.hpp"
#include "designer/design/design_check.hpp"
#include "designer/verify/simulation_verification.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

bool said(const DesignRecord& r, const std::string& text) {
  for (const auto& x : r.verdict.reasons)
    if (x.find(text) != std::string::npos) return true;
  return false;
}

// A run whose mean angle lies 5 deg above the reduced band's top: with a 2 SD band of +-12 deg
// alone the two overlap ("verified"); with the mean's 95 % interval of +-1 deg beside it they do
// not ("contradicted", the interval named); an interval that reaches the band verifies again.
TEST(SimulationVerification, TheDrumsAngleIsJudgedByItsMeansInterval) {
  const Case c = load_case("cases/rotating_drum_20rpm.toml");
  const DesignRecord design = design_check(c);
  const Estimate reduced = *find_estimate(design.results, "dynamic_angle_of_repose");
  ASSERT_TRUE(reduced.high);
  const double mean = *reduced.high + 5.0;
  const auto verify = [&](std::optional<double> interval) {
    SimulationVerification v;
    v.solver = Solver::dem;
    v.run.status = "done";
    v.run.results["dynamic_angle_of_repose"] = {{"value", mean},      {"unit", "deg"},
                                                {"low", mean - 12.0}, {"high", mean + 12.0},
                                                {"model", "DEM"},     {"rung", "L3"}};
    v.run.results["dynamic_angle_of_repose_reduced_model"] = {
        {"value", std::get<double>(reduced.value)},
        {"unit", "deg"},
        {"low", *reduced.low},
        {"high", *reduced.high},
        {"model", reduced.model},
        {"rung", "L0"}};
    if (interval)
      v.run.results["dynamic_angle_of_repose_interval"] = {
          {"value", *interval}, {"unit", "deg"}, {"model", "interval"}, {"rung", "L3"}};
    DesignRecord r = design;
    apply_simulation_verification(c, v, r);
    return r;
  };
  EXPECT_TRUE(said(verify(std::nullopt), "dynamic angle of repose verified"));
  const DesignRecord tight = verify(1.0);
  EXPECT_TRUE(said(tight, "dynamic angle of repose contradicted"));
  EXPECT_TRUE(said(tight, "its mean's 95 % interval +-1 deg"));
  EXPECT_TRUE(said(verify(5.5), "dynamic angle of repose verified"));
}

}  // namespace
}  // namespace feedflow
