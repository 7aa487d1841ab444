// The flow threshold's bisection allowed to widen its band (a stopping layer's thickness): a
// threshold above or below the band is still bracketed, by doubling the top or halving the
// bottom, until the ceiling or the floor ends it.
#include <gtest/gtest.h>

#include <cmath>

#include "designer/verify/threshold_bisection.hpp"

namespace feedflow {
namespace {

// A layer that comes to rest below `threshold` and flows from it on; counts its runs.
auto flows_from(double threshold, int& calls) {
  return [threshold, &calls](double h) -> std::optional<bool> {
    ++calls;
    return h >= threshold;
  };
}

// A threshold above the band (37 mm, band 10-20 mm): the top rests, so the band doubles to
// 40 mm, which flows; the bracket [20, 40] then halves to 5 mm: 30 rests, 35 rests.
TEST(ThresholdBisection, ATopThatStopsDoublesUntilItFlows) {
  int calls = 0;
  const auto b = bisect_flow_threshold(0.010, 0.020, 0.005, flows_from(0.037, calls), 0.003, 0.120);
  ASSERT_EQ(b.end, ThresholdBisection::End::bracketed);
  EXPECT_DOUBLE_EQ(b.stops_at, 0.035);
  EXPECT_DOUBLE_EQ(b.flows_at, 0.040);
  ASSERT_EQ(b.steps.size(), 4u);  // 20, 40, 30, 35: the bottom is never asked
  EXPECT_DOUBLE_EQ(b.steps[1].size, 0.040);
  EXPECT_EQ(calls, 4);
}

// A threshold below the band (4 mm, band 10-20 mm): the top flows, the bottom flows, so it halves
// to 5 mm (flows), then 3 mm, the floor (rests); the bracket [3, 5] is within 2 mm.
TEST(ThresholdBisection, ABottomThatFlowsHalvesDownToTheFloor) {
  int calls = 0;
  const auto b = bisect_flow_threshold(0.010, 0.020, 0.002, flows_from(0.004, calls), 0.003, 0.120);
  ASSERT_EQ(b.end, ThresholdBisection::End::bracketed);
  EXPECT_DOUBLE_EQ(b.stops_at, 0.003);
  EXPECT_DOUBLE_EQ(b.flows_at, 0.005);
  EXPECT_EQ(calls, 4);  // 20, 10, 5, 3
}

// The widening ends at the ceiling and the floor: a layer that rests at the ceiling puts the
// threshold above it, one that flows at the floor below it; without a floor or ceiling the
// band's own edges end it (the outlet width's search).
TEST(ThresholdBisection, TheCeilingAndTheFloorEndTheWidening) {
  int calls = 0;
  const auto above =
      bisect_flow_threshold(0.010, 0.020, 0.002, flows_from(0.5, calls), 0.003, 0.120);
  EXPECT_EQ(above.end, ThresholdBisection::End::stops_at_high_edge);
  EXPECT_DOUBLE_EQ(above.stops_at, 0.120);
  EXPECT_EQ(calls, 4);  // 20, 40, 80, 120
  calls = 0;
  const auto below =
      bisect_flow_threshold(0.010, 0.020, 0.002, flows_from(0.001, calls), 0.003, 0.120);
  EXPECT_EQ(below.end, ThresholdBisection::End::flows_at_low_edge);
  EXPECT_DOUBLE_EQ(below.flows_at, 0.003);
  calls = 0;
  const auto banded = bisect_flow_threshold(0.010, 0.020, 0.002, flows_from(0.5, calls));
  EXPECT_EQ(banded.end, ThresholdBisection::End::stops_at_high_edge);
  EXPECT_EQ(calls, 1);
  EXPECT_THROW(bisect_flow_threshold(0.010, 0.020, 0.002, flows_from(0.5, calls), 0.011, 0.120),
               std::invalid_argument);
}

}  // namespace
}  // namespace feedflow
