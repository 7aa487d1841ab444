#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fullsim/common/discharge_measurement.hpp"
#include "fullsim/dem/scene/flow_order.hpp"

namespace feedflow {
namespace {

// A synthetic discharge: closed until 0.5 s, a start-up over 0.5 s (rate ramping up), steady
// at `rate` with noise until 4 s, then an emptying tail at a quarter of the rate.
void synthetic(double rate, double noise, unsigned seed, std::vector<double>& t,
               std::vector<double>& m) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  const double dt = 0.01;
  double mass = 0.0;
  for (int k = 0; k <= 500; ++k) {
    const double time = k * dt;
    double q = 0.0;
    if (time > 0.5 && time <= 1.0) q = rate * (time - 0.5) / 0.5;
    else if (time > 1.0 && time <= 4.0) q = rate * (1.0 + noise * n(rng));
    else if (time > 4.0) q = 0.25 * rate;
    mass += std::max(0.0, q) * dt;
    t.push_back(time);
    m.push_back(mass);
  }
}

// The steady window drops the start-up ramp and the emptying tail, and the rate's 95 %
// interval holds the known rate (and is narrow: a few percent).
TEST(DischargeMeasurement, SteadyRateFromASyntheticSeriesHoldsTheKnownRate) {
  int covered = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::vector<double> t, m;
    synthetic(0.2, 0.3, seed, t, m);
    const SteadyRate r = steady_discharge_rate(t, m, 0.5);
    ASSERT_TRUE(r.found);
    EXPECT_GT(r.window_start, 0.75);
    EXPECT_LT(r.window_end, 4.3);
    EXPECT_GE(r.window_end - r.window_start, 1.0);
    EXPECT_LT(r.high - r.low, 0.1 * 0.2);
    covered += r.low <= 0.2 && 0.2 <= r.high;
  }
  EXPECT_GE(covered, 16);  // a 95 % interval covers the truth in (about) 19 of 20
}

// Too short a discharge has no steady window.
TEST(DischargeMeasurement, TooFewBatchesGiveNoSteadyRate) {
  const std::vector<double> t{0.0, 0.1, 0.2}, m{0.0, 0.01, 0.02};
  EXPECT_FALSE(steady_discharge_rate(t, m, 0.0).found);
}

// Arched needs both: nothing out for the quiet time and (almost) no motion; an empty hopper
// is "emptied", not arched. The last discharge is the end of the last sample interval that
// carried more than the trickle.
TEST(DischargeMeasurement, ArchedOnlyWhenQuietAndStill) {
  const double mass = 1.0;
  EXPECT_EQ(discharge_state(2.0, 1.0, 1e-6, mass, 100), DischargeState::arched);
  EXPECT_EQ(discharge_state(2.0, 1.8, 1e-6, mass, 100), DischargeState::flowing);  // recent exit
  EXPECT_EQ(discharge_state(2.0, 1.0, 1e-2, mass, 100), DischargeState::flowing);  // still moving
  EXPECT_EQ(discharge_state(2.0, 1.0, 0.0, 0.0, 0), DischargeState::emptied);
  const std::vector<double> t{0.0, 0.1, 0.2, 0.3, 0.4}, m{0.0, 0.5, 0.5001, 0.6, 0.6001};
  EXPECT_DOUBLE_EQ(last_discharge_time(t, m, 0.0, 0.01), 0.3);  // 0.2 -> 0.3 carried 1 kg/s
  EXPECT_DOUBLE_EQ(last_discharge_time(t, m, 0.35, 0.01), 0.35);  // nothing after 0.35
  EXPECT_DOUBLE_EQ(last_discharge_time(t, m, 0.0, 0.0), 0.4);     // any exit counts at zero trickle
}

// First in, first out: bands leaving in order give F = 1 (mass flow); the top band leaving
// first while the bottom band stays behind gives F near 0 (funnel flow).
TEST(FlowOrder, FifoIndexTellsMassFromFunnelFlow) {
  const FlowOrder ordered = flow_order({0, 0, 1, 1, 2, 2}, {});
  EXPECT_DOUBLE_EQ(ordered.fifo_index, 1.0);
  EXPECT_EQ(ordered.label(), "mass");
  const FlowOrder funnel = flow_order({2, 2, 1, 1}, {0, 0});
  EXPECT_DOUBLE_EQ(funnel.fifo_index, 0.0);
  EXPECT_EQ(funnel.label(), "funnel");
  // Random order: about one half.
  std::vector<int> mixed;
  for (int k = 0; k < 300; ++k) mixed.push_back((k * 7) % 3);
  EXPECT_NEAR(flow_order(mixed, {}).fifo_index, 0.5, 0.05);
}

}  // namespace
}  // namespace feedflow
