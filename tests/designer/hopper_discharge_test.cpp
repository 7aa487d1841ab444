// The hopper discharge measurement both full rungs use (designer/simulate/hopper_discharge.hpp):
// the same mass-time series gives the same q_m, interval and state whether it comes as the DEM
// adapter's rows (time after the opening) or the CEL adapter's (time from the start of the run,
// the gravity phase first), and the arching rule is one rule: a trickle below 2 % of the scale
// rate with a still bed is an arch, more is flow.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "designer/simulate/hopper_discharge.hpp"

namespace feedflow {
namespace {

// Rows every 10 ms: closed for `closed` s, a 0.3 s start-up, then `rate` kg/s with noise, then
// nothing for the last `stopped` s.
HopperDischarge::Rows discharge(double t0, double closed, double rate, double duration, double stopped,
                                double trickle = 0.0) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.2);
  HopperDischarge::Rows r;
  double m = 0.0;
  for (int k = 0; k * 0.01 <= duration + 1e-9; ++k) {
    const double t = k * 0.01;
    double q = 0.0;
    if (t > closed && t <= closed + 0.3) q = rate * (t - closed) / 0.3;
    else if (t > closed + 0.3 && t <= duration - stopped) q = rate * (1.0 + noise(rng));
    else if (t > duration - stopped) q = trickle;
    m += std::max(0.0, q) * 0.01;
    r.time.push_back(t0 + t);
    r.discharged.push_back(m);
  }
  r.mass_left = 10.0;
  r.kinetic_energy = 1e-6;
  return r;
}

HopperDischarge rule(double opening) {
  HopperDischarge d;
  d.opening = opening;
  d.trickle_rate = 0.02 * 2.0;  // 2 % of a 2 kg/s scale rate
  d.fill_mass = 20.0;
  return d;
}

// One estimator: the DEM's rows (opening at 0) and the CEL's (opening 1.37 s into the run) give
// the same steady rate, interval and window, and the interval holds the true 1.5 kg/s.
TEST(HopperDischarge, SameSeriesSameRateOnEitherRung) {
  const SteadyRate dem = rule(0.0).steady_rate(discharge(0.0, 0.0, 1.5, 3.0, 0.0));
  const SteadyRate cel = rule(1.37).steady_rate(discharge(1.37, 0.0, 1.5, 3.0, 0.0));
  ASSERT_TRUE(dem.found && cel.found);
  EXPECT_NEAR(cel.rate, dem.rate, 1e-9 * dem.rate);
  EXPECT_NEAR(cel.low, dem.low, 1e-9 * dem.rate);
  EXPECT_NEAR(cel.high, dem.high, 1e-9 * dem.rate);
  EXPECT_NEAR(cel.window_start - 1.37, dem.window_start, 1e-9);
  EXPECT_LE(dem.low, 1.5);
  EXPECT_GE(dem.high, 1.5);
  EXPECT_GE(dem.window_start, 0.25);  // the start-up is left out
}

// Arched: the flow stopped for more than the quiet time and the bed is still; a trickle under
// 2 % of the scale rate is still an arch, one of 5 % is flow, and a moving bed is not arched.
TEST(HopperDischarge, OneArchingRuleForBothRungs) {
  const HopperDischarge d = rule(0.0);
  EXPECT_EQ(d.state(discharge(0.0, 0.0, 1.5, 3.0, 0.6)), DischargeState::arched);
  EXPECT_EQ(d.state(discharge(0.0, 0.0, 1.5, 3.0, 0.6, 0.01 * 2.0)), DischargeState::arched);
  EXPECT_EQ(d.state(discharge(0.0, 0.0, 1.5, 3.0, 0.6, 0.05 * 2.0)), DischargeState::flowing);
  EXPECT_EQ(d.state(discharge(0.0, 0.0, 1.5, 3.0, 0.3)), DischargeState::flowing);  // not quiet for long
  HopperDischarge::Rows moving = discharge(0.0, 0.0, 1.5, 3.0, 0.6);
  moving.kinetic_energy = 1.0;
  EXPECT_EQ(d.state(moving), DischargeState::flowing);
  HopperDischarge::Rows empty = discharge(0.0, 0.0, 1.5, 3.0, 0.6);
  empty.mass_left = 0.0;
  EXPECT_EQ(d.state(empty), DischargeState::emptied);
  EXPECT_NE(d.stop_reason(discharge(0.0, 0.0, 1.5, 3.0, 0.6)).find("arched"), std::string::npos);
}

// A steady discharge converges after 1.5 s of rows; with the earliest convergence at 2 s after
// the opening (the CEL cone's) it does not stop at 1.5 s and does at 2.5 s, on either time axis.
TEST(HopperDischarge, EarliestConvergenceHoldsTheStopBack) {
  for (double opening : {0.0, 1.37}) {
    HopperDischarge d = rule(opening);
    EXPECT_NE(d.stop_reason(discharge(opening, 0.0, 1.5, 1.5, 0.0)).find("converged"), std::string::npos);
    d.earliest_convergence = 2.0;
    EXPECT_EQ(d.stop_reason(discharge(opening, 0.0, 1.5, 1.5, 0.0)), "");
    EXPECT_NE(d.stop_reason(discharge(opening, 0.0, 1.5, 2.5, 0.0)).find("converged"), std::string::npos);
  }
}

// The flow pattern of a run whose flow line empties within the steady window (a short fill: the
// surface sinks through the line at 1.2 s of a 3 s window) is read over the window's part
// before that, and said so; a line never covered for 0.1 s gives no pattern and a note, not a
// silent gap.
TEST(HopperDischarge, FlowPatternOverTheWindowsPartBeforeTheLineEmptied) {
  const HopperDischarge d = rule(0.0);
  const HopperDischarge::Rows rows = discharge(0.0, 0.0, 1.5, 3.0, 0.0);
  DischargeWording w;
  w.speeds = "particle speeds";
  SpeedProfile mass_flow{{0.0, 0.01, 0.02, 0.03}, {1.0, 0.9, 0.8, 0.6}};
  SpeedProfileSeries emptied, never;
  for (int k = 0; k <= 300; ++k) {
    const double t = 0.01 * k;
    emptied.add(t, t <= 1.2 ? mass_flow : SpeedProfile{});
    never.add(t, SpeedProfile{});
  }
  DesignRecord record;
  ASSERT_TRUE(add_discharge_results(d, rows, emptied, w, record).found);
  auto result = [&record](const std::string& name) -> const Estimate* {
    for (const auto& [key, e] : record.results)
      if (key == name) return &e;
    return nullptr;
  };
  ASSERT_NE(result("flow_pattern"), nullptr);
  EXPECT_EQ(std::get<std::string>(result("flow_pattern")->value), "mass");
  EXPECT_NEAR(std::get<double>(result("wall_to_centre_speed_ratio")->value), 0.6, 1e-12);
  EXPECT_NE(result("wall_to_centre_speed_ratio")->model.find("-1.2 s, the steady window until the line emptied"),
            std::string::npos) << result("wall_to_centre_speed_ratio")->model;
  DesignRecord bare;
  add_discharge_results(d, rows, never, w, bare);
  for (const auto& [key, e] : bare.results) EXPECT_NE(key, "flow_pattern");
  ASSERT_FALSE(bare.verdict.reasons.empty());
  EXPECT_NE(bare.verdict.reasons.back().find("flow pattern not measured"), std::string::npos);
}

}  // namespace
}  // namespace feedflow
