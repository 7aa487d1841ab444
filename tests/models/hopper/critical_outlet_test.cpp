// Critical outlet width against cohesive arching: Jenike's B_c from the flow function and the
// flow factor, the static-arch second estimate, mechanical arching and the slot-length rule
// (reduced_models.md sections 1.4, 1.5 and test vectors T2, T3).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "models/hopper/critical_outlet.hpp"
#include "models/hopper/enstad_flow_factor.hpp"
#include "models/hopper/radial_stress_field.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

const auto kPlane = FlowGeometry::plane;
const auto kCone = FlowGeometry::conical;

// The worked example of section 1.4: sigma_c = 0.1 sigma1 + 50 Pa, rho_b = 290, theta = 30,
// delta = 50, phi_w = 8.5 deg, ff = 1.315 (RSF): sigma1* = 75.7 Pa, sigma_c,crit = 57.6 Pa,
// H = 1.167 and B_c = 23.6 mm.
TEST(HopperCriticalOutlet, WorkedExamplePine) {
  const auto field = solve_radial_stress_field(kPlane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree);
  ASSERT_TRUE(field.has_value());
  EXPECT_NEAR(field->flow_factor, 1.315, 0.0005);
  const auto o = jenike_critical_outlet(kPlane, 30 * kDegree, field->flow_factor,
                                        FlowFunction::linear(0.1, 50.0), BulkDensity::constant(290));
  EXPECT_EQ(o.outcome, ArchingOutcome::critical_width);
  EXPECT_NEAR(o.major_stress, 75.7, 0.05);
  EXPECT_NEAR(o.critical_strength, 57.6, 0.05);
  EXPECT_NEAR(o.arch_factor, 1.167, 0.0005);
  EXPECT_NEAR(o.width * 1e3, 23.6, 0.05);
}

// T2: sigma_c,crit = 1.82 kPa, rho_b = 900, theta = 29.5 deg: cone 0.514 m (H = 2.492),
// wedge 0.240 m (H = 1.164).
TEST(HopperCriticalOutlet, T2WidthFromCriticalStrength) {
  EXPECT_NEAR(jenike_arch_factor(kCone, 29.5 * kDegree), 2.492, 0.0005);
  EXPECT_NEAR(jenike_arch_factor(kPlane, 29.5 * kDegree), 1.164, 0.0005);
  EXPECT_NEAR(arching_width(jenike_arch_factor(kCone, 29.5 * kDegree), 1820, 900), 0.514, 0.0005);
  EXPECT_NEAR(arching_width(jenike_arch_factor(kPlane, 29.5 * kDegree), 1820, 900), 0.240, 0.0005);
}

// T3: UYS = sigma1^0.68 in kPa and ff = 1.4 give sigma_crit = 1.4^2.125 = 2.044 kPa; cone at
// 35 deg with rho_b = 1800 needs 0.299 m, the wedge 0.138 m (not the source's 0.2249 m).
TEST(HopperCriticalOutlet, T3PowerLawFlowFunction) {
  const auto ff_curve = FlowFunction::power_law(std::pow(1000.0, 0.32), 0.68);  // kPa law in Pa
  const auto p = critical_point(ff_curve, 1.4);
  EXPECT_EQ(p.outcome, ArchingOutcome::critical_width);
  EXPECT_NEAR(p.strength, 1000.0 * std::pow(1.4, 2.125), 1e-6);
  EXPECT_NEAR(p.strength, 2044, 0.5);
  const auto rho = BulkDensity::constant(1800);
  EXPECT_NEAR(jenike_critical_outlet(kCone, 35 * kDegree, 1.4, ff_curve, rho).width, 0.299, 0.0005);
  EXPECT_NEAR(jenike_critical_outlet(kPlane, 35 * kDegree, 1.4, ff_curve, rho).width, 0.138,
              0.0005);
}

// A table through the points of the linear flow function gives the closed-form critical point
// (Brent on the bracketing segment); read beyond its points it says it extrapolated.
TEST(HopperCriticalOutlet, TabulatedFlowFunctionMatchesLinear) {
  const auto table = FlowFunction::tabulated({20, 100, 400}, {52, 60, 90});
  const auto p = critical_point(table, 1.315);
  const auto q = critical_point(FlowFunction::linear(0.1, 50.0), 1.315);
  EXPECT_EQ(p.outcome, ArchingOutcome::critical_width);
  EXPECT_NEAR(p.major_stress, q.major_stress, 1e-8);
  EXPECT_FALSE(p.extrapolated);
  const auto high = critical_point(FlowFunction::tabulated({1, 10}, {50.1, 51}), 1.315);
  EXPECT_NEAR(high.major_stress, q.major_stress, 1e-8);
  EXPECT_TRUE(high.extrapolated);
}

// The three outcomes in words: a cohesionless solid never arches cohesively (B_c = 0) whatever
// the form of its flow function; a flow function above the ff line needs flow aids.
TEST(HopperCriticalOutlet, CohesionlessAndHopelessLimits) {
  const auto rho = BulkDensity::constant(290);
  for (const auto& f : {FlowFunction::cohesionless(), FlowFunction::power_law(0.0, 0.5),
                        FlowFunction::tabulated({0, 1000}, {0, 0}),
                        FlowFunction::linear(0.5, 0.0)}) {
    const auto o = jenike_critical_outlet(kPlane, 30 * kDegree, 1.3, f, rho);
    EXPECT_EQ(o.outcome, ArchingOutcome::no_cohesive_arch) << f.describe();
    EXPECT_EQ(o.width, 0.0) << f.describe();
    EXPECT_NE(o.statement().find("B_c = 0"), std::string::npos);
  }
  for (const auto& f : {FlowFunction::linear(0.9, 50.0), FlowFunction::power_law(1.0, 1.2),
                        FlowFunction::tabulated({0, 100, 200}, {50, 100, 190})}) {
    const auto o = jenike_critical_outlet(kPlane, 30 * kDegree, 1.3, f, rho);
    EXPECT_EQ(o.outcome, ArchingOutcome::no_gravity_outlet) << f.describe();
    EXPECT_TRUE(std::isinf(o.width));
    EXPECT_NE(o.statement().find("flow aids"), std::string::npos);
  }
}

// B_c scales with the flow function's cohesion: doubling the intercept doubles it at constant
// density; compressible pine (denser at the higher arch stress) rises less.
TEST(HopperCriticalOutlet, RisesWithCohesion) {
  const double ff = 1.315;
  const auto rho = BulkDensity::constant(290);
  const double b1 =
      jenike_critical_outlet(kPlane, 30 * kDegree, ff, FlowFunction::linear(0.1, 50), rho).width;
  const double b2 =
      jenike_critical_outlet(kPlane, 30 * kDegree, ff, FlowFunction::linear(0.1, 100), rho).width;
  EXPECT_NEAR(b2 / b1, 2.0, 1e-12);
  HypoplasticParameters hp{47.3 * kDegree, 187.6e3, 0.30, 0.50, 1.06, 1.38, 0.3, 1.0};
  const auto pine = BulkDensity::compressible(BulkCompressibility(hp, 182.0, 1.38));
  const auto c1 =
      jenike_critical_outlet(kPlane, 30 * kDegree, ff, FlowFunction::linear(0.1, 50), pine);
  const auto c2 =
      jenike_critical_outlet(kPlane, 30 * kDegree, ff, FlowFunction::linear(0.1, 100), pine);
  EXPECT_GT(c2.width / c1.width, 1.8);
  EXPECT_LT(c2.width / c1.width, 2.0);
  // Critical-state density at p = sigma1* = 75.7 Pa: e_c = 0.928, rho_b = 224.7 kg/m^3, so the
  // loose arch needs a wider outlet than the 290 kg/m^3 estimate: 23.6 * 290/224.7 = 30.5 mm.
  EXPECT_NEAR(c1.bulk_density, 224.7, 0.5);
  EXPECT_NEAR(c1.width * 1e3, 30.5, 0.1);
  // A density table held at its end values gives the table's density.
  const auto table = BulkDensity::tabulated({0, 1000}, {200, 300});
  EXPECT_NEAR(jenike_critical_outlet(kPlane, 30 * kDegree, ff, FlowFunction::linear(0.1, 50), table)
                  .bulk_density, 200 + 0.1 * 75.7, 0.01);
}

// Section 1.5: H_a = 1.115 at (30, 8.5), 0.614 at (10, 8.5) and 1.259 at (40, 20) deg.
TEST(HopperCriticalOutlet, StaticArchFactorValues) {
  EXPECT_NEAR(static_arch_factor(30 * kDegree, 8.5 * kDegree), 1.115, 0.0005);
  EXPECT_NEAR(static_arch_factor(10 * kDegree, 8.5 * kDegree), 0.614, 0.0005);
  EXPECT_NEAR(static_arch_factor(40 * kDegree, 20 * kDegree), 1.259, 0.0005);
}

// Seed trend (section 0): the static arch rises with the semi-angle, 22 -> 32 -> 40 -> 47 mm
// at 10/20/30/45 deg for a stress-independent strength; the ratios follow H_a.
TEST(HopperCriticalOutlet, StaticArchRisesWithSemiAngle) {
  const auto f = FlowFunction::linear(0.0, 102.0);  // constant sigma_c ~ 102 Pa
  const auto rho = BulkDensity::constant(290);
  double widths[4];
  const double angles[4] = {10, 20, 30, 45};
  for (int i = 0; i < 4; ++i) {
    const double ff = enstad_flow_factor(kPlane, angles[i] * kDegree, 50 * kDegree, 8.5 * kDegree);
    widths[i] = static_arch_critical_outlet(angles[i] * kDegree, 8.5 * kDegree, ff, f, rho).width;
  }
  EXPECT_NEAR(widths[0] * 1e3, 22, 0.5);
  EXPECT_NEAR(widths[1] * 1e3, 32, 0.5);
  EXPECT_NEAR(widths[2] * 1e3, 40, 0.5);
  EXPECT_NEAR(widths[3] * 1e3, 47, 0.5);
}

// Section 0: Jenike alone barely rises with the semi-angle. Constant strength: +12.5 % from 20
// to 45 deg (H only). Power law (exponent 0.6) with the RSF ff: it falls, 68.6 -> 40 -> 39.2 mm
// at 10/30/45 deg, so B(10)/B(30) = 1.715 and B(45)/B(30) = 0.98.
TEST(HopperCriticalOutlet, JenikeTrendWithSemiAngle) {
  const auto rho = BulkDensity::constant(290);
  const auto width = [&](double theta, const FlowFunction& f) {
    const double ff =
        solve_radial_stress_field(kPlane, theta * kDegree, 50 * kDegree, 8.5 * kDegree)
            ->flow_factor;
    return jenike_critical_outlet(kPlane, theta * kDegree, ff, f, rho).width;
  };
  const auto constant = FlowFunction::linear(0.0, 100.0);
  EXPECT_NEAR(width(45, constant) / width(20, constant), 1.125, 1e-9);
  const auto power = FlowFunction::power_law(5.0, 0.6);
  EXPECT_NEAR(width(10, power) / width(30, power), 68.6 / 40.0, 0.01);
  EXPECT_NEAR(width(45, power) / width(30, power), 39.2 / 40.0, 0.01);
}

// Wall friction: with steep walls (10 deg) rougher walls lower ff and B_c; with flat walls
// (40 deg) they raise both (plane ff table: 1.86/1.33/1.17 and 1.23/1.30/1.65 for phi_w =
// 10/20/30 deg at delta = 50 deg).
TEST(HopperCriticalOutlet, TrendWithWallFriction) {
  const auto f = FlowFunction::linear(0.1, 50.0);
  const auto rho = BulkDensity::constant(290);
  const auto width = [&](double theta, double phi_w) {
    const double ff =
        solve_radial_stress_field(kPlane, theta * kDegree, 50 * kDegree, phi_w * kDegree)
            ->flow_factor;
    return jenike_critical_outlet(kPlane, theta * kDegree, ff, f, rho).width;
  };
  EXPECT_GT(width(10, 10), width(10, 20));
  EXPECT_GT(width(10, 20), width(10, 30));
  EXPECT_LT(width(40, 10), width(40, 20));
  EXPECT_LT(width(40, 20), width(40, 30));
  // The static arch always gains support from a rougher wall.
  EXPECT_LT(static_arch_factor(30 * kDegree, 5 * kDegree),
            static_arch_factor(30 * kDegree, 15 * kDegree));
}

// Mechanical arching (3-8 d_max) and the slot rule L >= 3B.
TEST(HopperCriticalOutlet, MechanicalArchingAndSlotLength) {
  const auto m = mechanical_arching_width(6e-3);
  EXPECT_DOUBLE_EQ(m.low, 18e-3);
  EXPECT_DOUBLE_EQ(m.high, 48e-3);
  EXPECT_DOUBLE_EQ(minimum_slot_length(0.06), 0.18);
  EXPECT_TRUE(slot_length_sufficient(0.18, 0.06));
  EXPECT_FALSE(slot_length_sufficient(0.17, 0.06));
  EXPECT_THROW(mechanical_arching_width(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace feedflow
