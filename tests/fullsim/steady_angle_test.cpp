// The drum's steady angle (fullsim/common/steady_angle): the start-up transient is dropped, the
// mean carries the confidence interval of its batch means, and a run converges only when that
// interval is within the tolerance.
#include "fullsim/common/steady_angle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace feedflow {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The 145 mm drum at 20 rpm on 10 mm cells, as measured (2026-12-06): lifted in the first 0.5 s,
// the first avalanche overshoots to about 63 deg at 1.2 s, and the angle falls by about 12 deg/s
// to 35 deg, around which it swings with an SD of about 4 deg. Samples every 0.02 s.
std::vector<AngleSample> drum_like(double until, double steady, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> swing(0.0, 4.0);
  std::vector<AngleSample> s;
  for (double t = 0.02; t <= until + 1e-9; t += 0.02) {
    double deg = 0.0;
    if (t < 0.5)
      deg = 0.7;  // flat: the bed is being lifted
    else if (t < 1.2)
      deg = 0.7 + (63.0 - 0.7) * (t - 0.5) / 0.7;
    else
      deg = std::max(steady, 63.0 - 12.0 * (t - 1.2));
    s.push_back({t, (deg + (t >= 0.5 ? swing(random) : 0.0)) * kDeg, true});
  }
  return s;
}

// Over 8 s the transient's batches are dropped: the mean is within 1 deg of the steady angle and
// its interval holds it; taking the whole run after the spin-up instead errs by several degrees.
TEST(SteadyAngle, DropsTheStartUpTransient) {
  const AngleWindows w = drum_angle_windows(20.0 * 2.0 * std::numbers::pi / 60.0);
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto samples = drum_like(8.0, 35.0, seed);
    const SteadyAngle a = steady_angle(samples, w);
    ASSERT_TRUE(a.found);
    EXPECT_GE(a.dropped, 3u) << seed;
    EXPECT_NEAR(a.angle / kDeg, 35.0, 1.0) << seed;
    EXPECT_LE(a.ci_low / kDeg, 35.0) << seed;
    EXPECT_GE(a.ci_high / kDeg, 35.0) << seed;
    double all = 0.0;
    int n = 0;
    for (const auto& x : samples)
      if (x.time > w.spin_up) all += x.angle / kDeg, ++n;
    EXPECT_GT(all / n - 35.0, 3.0) << seed;  // what the transient does to a plain mean
  }
}

// Checked at every sample, as a run does, convergence is not declared inside the transient (the
// old rule, two windows within 1 deg, stopped a 2.5 mm run at 1.66 s on the overshoot): when it is
// declared, the angle is within 2 deg of the steady one.
TEST(SteadyAngle, ConvergesOnlyPastTheTransient) {
  const AngleWindows w = drum_angle_windows(20.0 * 2.0 * std::numbers::pi / 60.0);
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    const auto samples = drum_like(20.0, 35.0, seed);
    std::vector<AngleSample> so_far;
    bool converged = false;
    for (const auto& x : samples) {
      so_far.push_back(x);
      if (!angle_converged(so_far, w)) continue;
      converged = true;
      const SteadyAngle a = steady_angle(so_far, w);
      EXPECT_GT(x.time, 3.0) << seed;
      EXPECT_NEAR(a.angle / kDeg, 35.0, 2.0) << seed << " at " << x.time << " s";
      EXPECT_LE(0.5 * (a.ci_high - a.ci_low), w.tolerance);
      EXPECT_FALSE(converged_reason(so_far, w).empty());
      break;
    }
    EXPECT_TRUE(converged) << seed;
  }
}

// A steady swing with no transient: the interval's half-width is Student's t over the batch means
// (half-width shrinking as the run grows), and a bed with no free surface has converged once the
// windows have passed.
TEST(SteadyAngle, IntervalShrinksWithTheRunAndABedWithoutSurfaceConverges) {
  AngleWindows w{0.5, 0.5, 1.0 * kDeg, 5, 0.95};
  std::vector<AngleSample> s;
  for (int k = 1; k <= 1000; ++k)
    s.push_back({0.02 * k, (40.0 + ((k / 25) % 2 ? 2.0 : -2.0)) * kDeg, true});
  const auto upto = [&](double t) {
    std::vector<AngleSample> part;
    for (const auto& x : s)
      if (x.time <= t + 1e-9) part.push_back(x);
    return steady_angle(part, w);
  };
  const SteadyAngle short_run = upto(6.0), long_run = upto(20.0);
  EXPECT_NEAR(long_run.angle / kDeg, 40.0, 0.1);
  EXPECT_LT(long_run.ci_high - long_run.ci_low, short_run.ci_high - short_run.ci_low);
  EXPECT_NEAR(long_run.sd / kDeg, 2.0, 1e-2);
  std::vector<AngleSample> turning;
  for (int k = 1; k <= 100; ++k) turning.push_back({0.02 * k, 0.0, false});
  EXPECT_TRUE(angle_converged(turning, w));
}

}  // namespace
}  // namespace feedflow
