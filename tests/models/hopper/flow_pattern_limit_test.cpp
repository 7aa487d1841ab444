// The conical existence limit of the radial stress field against the Arnold-McLean closed form
// (reduced_models.md sections 1.2 and 1.6, test vector T5).
#include <gtest/gtest.h>

#include <numbers>

#include "models/hopper/radial_stress_field.hpp"

namespace feedflow {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// T5 and the section 1.2 checks: where F(s0_min) = 0, at 26.1, 37.8, 20.1, 32.4 and 40.1 deg
// for (delta, phi_w) = (50,20), (50,10), (60,25), (40,16), (47.3,8.5), within 0.1 deg.
TEST(HopperFlowPattern, RadialFieldConicalLimitMatchesT5) {
  struct Case { double delta, phi_w, limit; };
  for (const auto& c : {Case{50, 20, 26.13}, Case{50, 10, 37.84}, Case{60, 25, 20.1},
                        Case{40, 16, 32.37}, Case{47.3, 8.5, 40.14}}) {
    const auto limit =
        radial_field_limit_angle(FlowGeometry::conical, c.delta * kDeg, c.phi_w * kDeg);
    ASSERT_TRUE(limit.has_value());
    EXPECT_NEAR(*limit / kDeg, c.limit, 0.1) << "delta " << c.delta << " phi_w " << c.phi_w;
  }
}

}  // namespace
}  // namespace feedflow
