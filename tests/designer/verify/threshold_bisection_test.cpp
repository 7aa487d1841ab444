// The flow threshold's bisection allowed to widen its band (a stopping layer's thickness): a
// threshold above or below the band is still bracketed, by doubling the top or halving the
// bottom, until the ceiling or the floor ends it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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

namespace feedflow {
namespace {

// The sizes a search asks for, as its runs' folders name them (mm to six decimals).
std::vector<std::string> names_asked(double low, double high, double grid) {
  std::vector<std::string> names;
  (void)bisect_flow_threshold(
      low, high, 0.003,
      [&](double h) -> std::optional<bool> {
        char text[32];
        std::snprintf(text, sizeof text, "%.6f", h / 1e-3);
        names.push_back(text);
        return h >= 0.009;
      },
      0.003, 0.120, grid);
  return names;
}

// A search started again from its band's edges as its runs are named (the 42 deg layers' band,
// 3.3759094 .. 12.9868704 mm) asks the layers the first search asked, to the micrometre; without
// the grid the second search's middle differs in the last digit (8.181389 against 8.181390 mm),
// so a layer cut short would be started afresh under another name instead of continued.
TEST(ThresholdBisection, OnAGridASearchStartedAgainAsksTheSameSizes) {
  const double low = 3.3759094e-3, high = 12.9868704e-3;
  // as their folders say, read back as the search reads them
  const double named_low = std::stod("3.375909") * 1e-3, named_high = std::stod("12.98687") * 1e-3;
  const auto first = names_asked(low, high, 1e-6), again = names_asked(named_low, named_high, 1e-6);
  EXPECT_EQ(first, again);
  for (std::size_t k = 2; k < first.size(); ++k)  // every middle on the micrometre grid
    EXPECT_EQ(first[k].substr(first[k].size() - 3), "000") << first[k];
  EXPECT_NE(names_asked(low, high, 0.0), names_asked(named_low, named_high, 0.0));
}

}  // namespace
}  // namespace feedflow
