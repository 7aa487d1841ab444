// Hopper geometry: the filled volume the discharge time is computed from.
#include <gtest/gtest.h>

#include <cmath>

#include "models/equipment/hopper.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

// Filled volumes by hand: a 30 deg wedge of the seed (B = 100 mm, bin 0.6 m, fill 0.68 m above
// the apex) and a 45 deg cone filled to its transition.
TEST(HopperVolume, MatchesHandGeometry) {
  Hopper wedge{"wedge", 30 * kDegree, 0.1, 0.68, 0.6, 1.0, std::nullopt};
  // Trapezoid from the outlet (h0 = 0.0866 m) to the transition (0.5196 m), then the bin.
  const double h0 = 0.05 / std::tan(30 * kDegree), ht = 0.3 / std::tan(30 * kDegree);
  const double area = 0.5 * (0.1 + 0.6) * (ht - h0) + 0.6 * (0.68 - ht);
  EXPECT_NEAR(wedge.filled_volume(), area, 1e-12);
  Hopper cone{"conical", 45 * kDegree, 0.0, 0.5, 1.0, std::nullopt, std::nullopt};
  EXPECT_NEAR(cone.filled_volume(), 3.14159265358979323846 / 3 * 0.5 * 0.5 * 0.5, 1e-12);  // pi r^2 h / 3
}

}  // namespace
}  // namespace feedflow
