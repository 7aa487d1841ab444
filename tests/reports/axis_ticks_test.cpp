// Chart axes: tick values and labels for ordinary and awkward ranges.
#include <gtest/gtest.h>

#include "reports/plot/axis_ticks.hpp"

namespace feedflow {
namespace {

std::string joined(const AxisTicks& t) {
  std::string s;
  for (const auto& l : t.labels) s += (s.empty() ? "" : " ") + l;
  return s;
}

// Ordinary ranges get 1-2-5 steps covering the data.
TEST(AxisTicks, OrdinaryRanges) {
  EXPECT_EQ(joined(linear_ticks(0, 10)), "0 2 4 6 8 10");
  EXPECT_EQ(joined(linear_ticks(10, 45)), "10 20 30 40 50");
  EXPECT_EQ(joined(linear_ticks(0, 60, 7)), "0 10 20 30 40 50 60");
  const auto t = linear_ticks(0.013, 0.061);
  EXPECT_LE(t.lower, 0.013);
  EXPECT_GE(t.upper, 0.061);
  EXPECT_EQ(joined(t), "0.01 0.02 0.03 0.04 0.05 0.06 0.07");
}

// Awkward ranges: tiny, huge, negative, a 2.5 step, and a single value.
TEST(AxisTicks, AwkwardRanges) {
  EXPECT_EQ(joined(linear_ticks(1e-5, 3e-5, 3)), "1e-5 2e-5 3e-5");
  EXPECT_EQ(joined(linear_ticks(2e6, 8e6, 4)), "2e6 4e6 6e6 8e6");
  EXPECT_EQ(joined(linear_ticks(-1, 1, 5)), "-1.0 -0.5 0 0.5 1.0");
  EXPECT_EQ(joined(linear_ticks(0, 1, 5)), "0 0.25 0.50 0.75 1.00");
  const auto single = linear_ticks(5, 5);  // a flat series still gets an axis around it
  EXPECT_LT(single.lower, 5);
  EXPECT_GT(single.upper, 5);
  EXPECT_GE(single.values.size(), 3u);
  EXPECT_EQ(joined(linear_ticks(0, 0)).find("nan"), std::string::npos);
  EXPECT_THROW(linear_ticks(0, std::numeric_limits<double>::infinity()), std::invalid_argument);
}

// Logarithmic axes tick at whole decades.
TEST(AxisTicks, LogarithmicDecades) {
  EXPECT_EQ(joined(log_ticks(0.02, 300)), "0.01 0.1 1 10 100 1000");
  EXPECT_EQ(joined(log_ticks(1e-6, 1e-5)), "1e-6 1e-5");
  EXPECT_THROW(log_ticks(0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace feedflow
