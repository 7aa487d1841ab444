// lane_math::exp and lane_math::log (the vectorisable forms the contact laws use) against the C
// library's, in units in the last place.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "models/numerics/lane_math.hpp"

namespace feedflow {
namespace {

// Distance in representable doubles between two positive finite values.
double ulps(double a, double b) {
  return std::abs(
      static_cast<double>(std::bit_cast<std::int64_t>(a) - std::bit_cast<std::int64_t>(b)));
}

// exp within 2 ulp of std::exp over the exponents the hysteretic law's tail takes (beta x from
// about -700 to 0) and the positive side, 0 exactly 1; below -708 it is clamped, not zero.
TEST(LaneMath, ExpIsWithinTwoUlpOfTheLibrary) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-708.0, 709.0);
  std::uniform_real_distribution<double> small(-1e-3, 1e-3);
  double worst = 0.0;
  for (int k = 0; k < 200000; ++k) {
    const double x = k % 2 ? u(rng) : small(rng);
    worst = std::max(worst, ulps(lane_math::exp(x), std::exp(x)));
  }
  std::printf("exp: worst %.0f ulp\n", worst);
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(lane_math::exp(0.0), 1.0);
  EXPECT_GT(lane_math::exp(-1000.0), 0.0);
  EXPECT_TRUE(std::isfinite(lane_math::exp(1000.0)));
}

// log within 2 ulp of std::log from 1e-300 to 1e300, and near 1 (the law takes ln(1 + small)).
TEST(LaneMath, LogIsWithinTwoUlpOfTheLibrary) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> decade(-300.0, 300.0);
  std::uniform_real_distribution<double> near_one(-1e-3, 1e-3);
  double worst = 0.0;
  for (int k = 0; k < 200000; ++k) {
    const double y = k % 2 ? std::pow(10.0, decade(rng)) : 1.0 + near_one(rng);
    if (y == 1.0) continue;
    worst = std::max(worst, ulps(lane_math::log(y), std::log(y)));
  }
  std::printf("log: worst %.0f ulp\n", worst);
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(lane_math::log(1.0), 0.0);
  for (const double y :
       {std::nextafter(std::sqrt(2.0), 1.0), std::sqrt(2.0), std::nextafter(std::sqrt(2.0), 2.0)})
    EXPECT_LE(ulps(lane_math::log(y), std::log(y)), 2.0) << y;  // either side of the fold
}

}  // namespace
}  // namespace feedflow
