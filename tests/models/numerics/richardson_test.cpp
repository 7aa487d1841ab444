#include "models/numerics/richardson.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "models/numerics/pareto_front.hpp"

namespace feedflow {
namespace {

// f(h) = limit + c h^p exactly: the observed order is p and the extrapolation is the limit
// (first and second order, refined by 2 and by 3).
TEST(Richardson, RecoversOrderAndLimitOfAPowerLaw) {
  for (double p : {1.0, 2.0})
    for (double r : {2.0, 3.0}) {
      const std::array<double, 3> h{0.02, 0.02 / r, 0.02 / (r * r)};
      std::array<double, 3> f;
      for (int k = 0; k < 3; ++k) f[k] = 5.75 + 40.0 * std::pow(h[k], p);
      const RichardsonEstimate e = richardson(h, f);
      ASSERT_TRUE(e.order);
      EXPECT_NEAR(*e.order, p, 1e-9);
      EXPECT_NEAR(e.value, 5.75, 1e-9);
      EXPECT_TRUE(e.asymptotic);
    }
}

// With a higher-order term the extrapolation is not exact, but its error bar (GCI, safety 1.25)
// holds the true limit, and it is closer to it than the finest value.
TEST(Richardson, ErrorBarHoldsTheLimitWithAHigherOrderTerm) {
  const std::array<double, 3> h{0.02, 0.01, 0.005};
  std::array<double, 3> f;
  for (int k = 0; k < 3; ++k) f[k] = 2.0 + 10.0 * h[k] + 200.0 * h[k] * h[k];
  const RichardsonEstimate e = richardson(h, f);
  EXPECT_LE(std::abs(e.value - 2.0), e.error_bar);
  EXPECT_LT(std::abs(e.value - 2.0), std::abs(f[2] - 2.0));
  EXPECT_GT(*e.order, 1.0);  // between the two terms' orders
  EXPECT_LT(*e.order, 2.0);
}

// Differences that change sign (oscillating convergence) give no order: the finest value with
// the widest spread as its error bar, flagged as outside the asymptotic range.
TEST(Richardson, OscillatingValuesHaveNoOrder) {
  const RichardsonEstimate e = richardson({0.02, 0.01, 0.005}, {6.21, 5.75, 5.9});
  EXPECT_FALSE(e.order);
  EXPECT_FALSE(e.asymptotic);
  EXPECT_DOUBLE_EQ(e.value, 5.9);
  EXPECT_NEAR(e.error_bar, 0.46, 1e-12);
  EXPECT_FALSE(e.diverging);
}

// Differences of one sign that grow (each refinement moves the value more: the drum at 20 rpm,
// 36.08 / 43.05 / 52.01 deg on 10 / 5 / 2.5 mm) give no order either, and are called diverging.
TEST(Richardson, GrowingDifferencesDivergeWithoutAnOrder) {
  const RichardsonEstimate e = richardson({0.01, 0.005, 0.0025}, {36.08, 43.05, 52.01});
  EXPECT_FALSE(e.order);
  EXPECT_TRUE(e.diverging);
  EXPECT_DOUBLE_EQ(e.value, 52.01);
  EXPECT_NEAR(e.error_bar, 15.93, 1e-9);
}

// Resolutions that do not shrink by one ratio, or do not shrink, are refused.
TEST(Richardson, RefusesResolutionsWithoutOneRatio) {
  EXPECT_THROW(richardson({0.02, 0.01, 0.004}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(richardson({0.01, 0.02, 0.04}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(richardson({0.02, 0.01, 0.005}, {1, NAN, 3}), std::invalid_argument);
}

// Two levels with the formal order: exact for a pure power law of that order, error bar three
// times the correction (Roache's two-grid safety factor).
TEST(Richardson, TwoLevelsWithTheFormalOrder) {
  const RichardsonEstimate e = richardson_two_levels({0.02, 0.01}, {1.0 + 0.02, 1.0 + 0.01}, 1.0);
  EXPECT_NEAR(e.value, 1.0, 1e-12);
  EXPECT_NEAR(e.error_bar, 3.0 * 0.01, 1e-12);
}

// The front of run time against error: the cheapest, the most accurate and what no other point
// beats on both; ties on one axis are broken by the other; non-finite points are off it.
TEST(ParetoFront, KeepsWhatNoOtherPointBeatsOnBoth) {
  //                              0     1     2     3     4     5       6
  const std::vector<double> cost{1.0, 2.0, 3.0, 2.5, 10.0, 2.0, NAN};
  const std::vector<double> err{0.5, 0.2, 0.3, 0.1, 0.01, 0.25, 0.0};
  const std::vector<bool> on = pareto_front(cost, err);
  EXPECT_EQ(on, (std::vector<bool>{true, true, false, true, true, false, false}));
}

}  // namespace
}  // namespace feedflow
