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

// The largest distance in ulp between `ours` and `library` over 200 000 arguments drawn by
// `draw(rng, k)` from a generator seeded with `seed`.
template <class Ours, class Library, class Draw>
double worst_ulps(unsigned seed, Ours ours, Library library, Draw draw) {
  std::mt19937_64 rng(seed);
  double worst = 0.0;
  for (int k = 0; k < 200000; ++k) {
    const double x = draw(rng, k);
    worst = std::max(worst, ulps(ours(x), library(x)));
  }
  return worst;
}

// exp within 2 ulp of std::exp over the exponents the hysteretic law's tail takes (beta x from
// about -700 to 0) and the positive side, 0 exactly 1; below -708 it is clamped, not zero.
TEST(LaneMath, ExpIsWithinTwoUlpOfTheLibrary) {
  std::uniform_real_distribution<double> u(-708.0, 709.0);
  std::uniform_real_distribution<double> small(-1e-3, 1e-3);
  const double worst = worst_ulps(
      3, [](double x) { return lane_math::exp(x); }, [](double x) { return std::exp(x); },
      [&](std::mt19937_64& rng, int k) { return k % 2 ? u(rng) : small(rng); });
  std::printf("exp: worst %.0f ulp\n", worst);
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(lane_math::exp(0.0), 1.0);
  EXPECT_GT(lane_math::exp(-1000.0), 0.0);
  EXPECT_TRUE(std::isfinite(lane_math::exp(1000.0)));
}

// log within 2 ulp of std::log from 1e-300 to 1e300, and near 1 (the law takes ln(1 + small)).
TEST(LaneMath, LogIsWithinTwoUlpOfTheLibrary) {
  std::uniform_real_distribution<double> decade(-300.0, 300.0);
  std::uniform_real_distribution<double> near_one(-1e-3, 1e-3);
  const double worst = worst_ulps(
      5, [](double y) { return lane_math::log(y); }, [](double y) { return std::log(y); },
      [&](std::mt19937_64& rng, int k) {
        return k % 2 ? std::pow(10.0, decade(rng)) : 1.0 + near_one(rng);
      });
  std::printf("log: worst %.0f ulp\n", worst);
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(lane_math::log(1.0), 0.0);
  for (const double y :
       {std::nextafter(std::sqrt(2.0), 1.0), std::sqrt(2.0), std::nextafter(std::sqrt(2.0), 2.0)})
    EXPECT_LE(ulps(lane_math::log(y), std::log(y)), 2.0) << y;  // either side of the fold
}

}  // namespace
}  // namespace feedflow
