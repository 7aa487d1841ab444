// The conical existence limit of the radial stress field against the Arnold-McLean closed form
// (reduced_models.md sections 1.2 and 1.6, test vector T5).
#include <gtest/gtest.h>

#include "models/hopper/flow_pattern.hpp"
#include "models/hopper/radial_stress_field.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

// T5 and the section 1.2 checks: where F(s0_min) = 0, at 26.1, 37.8, 20.1, 32.4 and 40.1 deg
// for (delta, phi_w) = (50,20), (50,10), (60,25), (40,16), (47.3,8.5), within 0.1 deg.
TEST(HopperFlowPattern, RadialFieldConicalLimitMatchesT5) {
  struct Case { double delta, phi_w, limit; };
  for (const auto& c : {Case{50, 20, 26.13}, Case{50, 10, 37.84}, Case{60, 25, 20.1},
                        Case{40, 16, 32.37}, Case{47.3, 8.5, 40.14}}) {
    const auto limit =
        radial_field_limit_angle(FlowGeometry::conical, c.delta * kDegree, c.phi_w * kDegree);
    ASSERT_TRUE(limit.has_value());
    EXPECT_NEAR(*limit / kDegree, c.limit, 0.1) << "delta " << c.delta << " phi_w " << c.phi_w;
  }
}

// Section 1.6 and T4/T5: the Arnold-McLean conical boundary 26.1, 39.6, 40.1, 32.4, 37.8 and
// 20.1 deg for (delta, phi_w) = (50,20), (50,8.5), (47.3,8.5), (40,16), (50,10), (60,25).
TEST(HopperFlowPattern, ConicalArnoldMcLeanBoundary) {
  struct Case { double delta, phi_w, limit; };
  for (const auto& c : {Case{50, 20, 26.1}, Case{50, 8.5, 39.6}, Case{47.3, 8.5, 40.1},
                        Case{40, 16, 32.4}, Case{50, 10, 37.8}, Case{60, 25, 20.1}})
    EXPECT_NEAR(conical_mass_flow_limit(c.delta * kDegree, c.phi_w * kDegree) / kDegree, c.limit,
                0.05)
        << "delta " << c.delta << " phi_w " << c.phi_w;
}

// The closed form and the RSF existence limit (F(s0_min) = 0) agree within 0.05 deg.
TEST(HopperFlowPattern, ClosedFormEqualsRadialFieldLimit) {
  for (double delta : {40.0, 50.0, 60.0})
    for (double phi_w : {8.5, 15.0, 25.0}) {
      const auto rsf =
          radial_field_limit_angle(FlowGeometry::conical, delta * kDegree, phi_w * kDegree);
      ASSERT_TRUE(rsf.has_value());
      EXPECT_NEAR(*rsf / kDegree,
                  conical_mass_flow_limit(delta * kDegree, phi_w * kDegree) / kDegree, 0.05)
          << "delta " << delta << " phi_w " << phi_w;
    }
}

// The seed's lab wedge (30 deg, phi_w 8.5 deg, delta 50 deg) is mass flow, far from the
// boundary; the wedge limit is the interim rule (conical + 10, band 8-12 deg) and says so.
TEST(HopperFlowPattern, SeedWedgeIsMassFlowByTheInterimRule) {
  const auto v =
      classify_flow_pattern(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree);
  EXPECT_EQ(v.pattern, FlowPattern::mass);
  EXPECT_FALSE(v.near_boundary) << v.reason;
  EXPECT_NE(v.limit.model.find("interim"), std::string::npos);
  EXPECT_NEAR(v.limit.nominal / kDegree, 39.6 + 10, 0.05);
  EXPECT_NEAR(v.limit.low / kDegree, 39.6 + 8, 0.05);
  EXPECT_NEAR(v.limit.high / kDegree, 39.6 + 12, 0.05);
  EXPECT_NEAR(v.margin / kDegree, 19.6, 0.05);
  EXPECT_GT(v.flow_factor_ratio, 1.0);
  EXPECT_LT(v.flow_factor_ratio, 1.1);
}

// Past the boundary the pattern is funnel, for cones and wedges; within 3 deg of it, mass flow
// is flagged as near the boundary.
TEST(HopperFlowPattern, PastTheBoundaryIsFunnel) {
  const double d = 50 * kDegree, w = 20 * kDegree;  // conical limit 26.1 deg, wedge 36.1 deg
  EXPECT_EQ(classify_flow_pattern(FlowGeometry::conical, 27 * kDegree, d, w).pattern,
            FlowPattern::funnel);
  EXPECT_EQ(classify_flow_pattern(FlowGeometry::plane, 37 * kDegree, d, w).pattern,
            FlowPattern::funnel);
  const auto near = classify_flow_pattern(FlowGeometry::conical, 24 * kDegree, d, w);
  EXPECT_EQ(near.pattern, FlowPattern::mass);
  EXPECT_TRUE(near.near_boundary);
  EXPECT_NE(near.reason.find("near the boundary"), std::string::npos);
  EXPECT_FALSE(classify_flow_pattern(FlowGeometry::conical, 15 * kDegree, d, w).near_boundary);
  // The wedge is near its boundary from 3 deg below the band's low end (34.1 deg) on.
  EXPECT_TRUE(classify_flow_pattern(FlowGeometry::plane, 32 * kDegree, d, w).near_boundary);
  EXPECT_FALSE(classify_flow_pattern(FlowGeometry::plane, 30 * kDegree, d, w).near_boundary);
}

// The ff > 1.5 min ff criterion looks only at the flat-wall side: the high ff of very steep
// walls (2.51 at 5 deg for the seed wedge, twice its minimum) is not "near the boundary";
// towards flat walls it is (delta 30, phi_w 25 deg: ff 1.65 times its minimum at 28 deg).
TEST(HopperFlowPattern, SteepWallsAreNotNearTheBoundary) {
  const auto v =
      classify_flow_pattern(FlowGeometry::plane, 5 * kDegree, 50 * kDegree, 8.5 * kDegree);
  EXPECT_GT(v.flow_factor_ratio, 1.5);
  EXPECT_FALSE(v.near_boundary) << v.reason;
  const auto flat =
      classify_flow_pattern(FlowGeometry::plane, 28 * kDegree, 30 * kDegree, 25 * kDegree);
  EXPECT_EQ(flat.pattern, FlowPattern::mass);
  EXPECT_GT(flat.flow_factor_ratio, 1.5);
  EXPECT_NE(flat.reason.find("times its minimum"), std::string::npos) << flat.reason;
}

}  // namespace
}  // namespace feedflow
