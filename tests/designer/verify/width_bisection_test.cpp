// Bisection on the outlet width with a flows/arches judge, on synthetic judges whose critical
// width is set: the bracket holds the set width and is narrower than the tolerance, in the
// number of runs the plan states; a critical width outside the band ends at the edge that shows
// it; a judge without an answer stops the search.
#include <gtest/gtest.h>

#include "designer/verify/width_bisection.hpp"

namespace feedflow {
namespace {

// A hopper that arches below `critical` and flows from it on.
auto judge_with(double critical, int& calls) {
  return [critical, &calls](double w) -> std::optional<OutletOutcome> {
    ++calls;
    return w < critical ? OutletOutcome::arches : OutletOutcome::flows;
  };
}

// Converges to the set width: for set widths across the band (20-42 mm, the pilot's B_c band),
// the bracket holds it, is at most 1 mm wide, and took 2 + ceil(log2(22 / 1)) = 7 runs.
TEST(WidthBisection, BracketsTheSetWidthWithinTheTolerance) {
  for (double critical : {0.0205, 0.0251, 0.03058, 0.0377, 0.0419}) {
    int calls = 0;
    const auto b = bisect_outlet_width(0.020, 0.042, 0.001, judge_with(critical, calls));
    ASSERT_EQ(b.end, WidthBisection::End::bracketed) << critical;
    EXPECT_LT(b.arches_at, critical);
    EXPECT_GE(b.flows_at, critical);
    EXPECT_LE(b.flows_at - b.arches_at, 0.001);
    EXPECT_EQ(calls, bisection_runs(0.020, 0.042, 0.001));
    EXPECT_EQ(calls, 7);
    EXPECT_EQ(b.steps.size(), 7u);
  }
}

// The band's top judged first: an arch there ends the search in one run (the critical width is
// above the band); a flow at the bottom ends it in two (below the band).
TEST(WidthBisection, OutsideTheBandEndsAtTheEdgeThatShowsIt) {
  int calls = 0;
  const auto above = bisect_outlet_width(0.020, 0.042, 0.001, judge_with(0.050, calls));
  EXPECT_EQ(above.end, WidthBisection::End::arches_at_high_edge);
  EXPECT_EQ(calls, 1);
  EXPECT_DOUBLE_EQ(above.arches_at, 0.042);
  calls = 0;
  const auto below = bisect_outlet_width(0.020, 0.042, 0.001, judge_with(0.015, calls));
  EXPECT_EQ(below.end, WidthBisection::End::flows_at_low_edge);
  EXPECT_EQ(calls, 2);
  EXPECT_DOUBLE_EQ(below.flows_at, 0.020);
}

// A judge that gives no answer (an interrupted run) stops the search with what it had.
TEST(WidthBisection, NoAnswerStops) {
  int calls = 0;
  const auto b =
      bisect_outlet_width(0.020, 0.042, 0.001, [&](double w) -> std::optional<OutletOutcome> {
        if (++calls == 3) return std::nullopt;
        return w < 0.03 ? OutletOutcome::arches : OutletOutcome::flows;
      });
  EXPECT_EQ(b.end, WidthBisection::End::stopped);
  EXPECT_EQ(b.steps.size(), 2u);
  EXPECT_THROW(bisect_outlet_width(0.04, 0.02, 0.001, judge_with(0.03, calls)),
               std::invalid_argument);
}

}  // namespace
}  // namespace feedflow
