// Hopper flow factor: Enstad/Arnold-McLean closed form and Jenike's radial stress field
// against the reference values of reduced_models.md section 1.2 (table T6, precise points, T4).
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "models/hopper/enstad_flow_factor.hpp"
#include "models/hopper/radial_stress_field.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

struct TableRow {
  double delta, phi_w;
  std::array<double, 5> rsf, enstad;  // theta = 10, 20, 30, 40, 50 deg
};

// reduced_models.md section 1.2, plane (m = 0) rows, as (RSF, Enstad) per semi-angle.
constexpr TableRow kPlaneTable[] = {
    {40, 10, {2.07, 1.69, 1.51, 1.45, 1.49}, {2.11, 1.76, 1.62, 1.58, 1.64}},
    {40, 20, {1.45, 1.38, 1.40, 1.51, 1.74}, {1.49, 1.47, 1.52, 1.66, 1.90}},
    {50, 10, {1.86, 1.46, 1.28, 1.23, 1.29}, {1.88, 1.49, 1.32, 1.26, 1.28}},
    {50, 20, {1.33, 1.22, 1.21, 1.30, 1.55}, {1.34, 1.25, 1.24, 1.30, 1.43}},
    {50, 30, {1.17, 1.21, 1.34, 1.65, 2.29}, {1.19, 1.23, 1.34, 1.53, 1.83}},
    {60, 20, {1.26, 1.13, 1.11, 1.20, 1.47}, {1.26, 1.13, 1.10, 1.12, 1.21}},
    {50, 8.5, {2.01, 1.53, 1.31, 1.24, 1.27}, {2.03, 1.56, 1.35, 1.27, 1.27}},
};

// Every Enstad cell of the plane table (T6) within the stated +-0.01 (tests the corrected
// [2(1-cos)]^m term: the misprinted 2(1-cos)^m would give 1.7-1.9).
TEST(HopperFlowFactor, EnstadPlaneTableEveryCell) {
  for (const auto& row : kPlaneTable)
    for (int i = 0; i < 5; ++i) {
      const double theta = 10.0 * (i + 1);
      EXPECT_NEAR(enstad_flow_factor(FlowGeometry::plane, theta * kDegree, row.delta * kDegree,
                                     row.phi_w * kDegree),
                  row.enstad[i], 0.01)
          << "delta " << row.delta << " phi_w " << row.phi_w << " theta " << theta;
    }
}

// Every RSF cell of the plane table (T6) within +-0.01: the shooting solves each case.
TEST(HopperFlowFactor, RadialStressFieldPlaneTableEveryCell) {
  for (const auto& row : kPlaneTable)
    for (int i = 0; i < 5; ++i) {
      const double theta = 10.0 * (i + 1);
      const auto field = solve_radial_stress_field(FlowGeometry::plane, theta * kDegree,
                                                   row.delta * kDegree, row.phi_w * kDegree);
      ASSERT_TRUE(field.has_value()) << "delta " << row.delta << " theta " << theta;
      EXPECT_NEAR(field->flow_factor, row.rsf[i], 0.01)
          << "delta " << row.delta << " phi_w " << row.phi_w << " theta " << theta;
    }
}

struct PrecisePoint {
  FlowGeometry g;
  double theta, delta, phi_w, s0, s_w, ff;
};

// reduced_models.md section 1.2, precise single points (s0, s_w, ff).
constexpr PrecisePoint kPrecisePoints[] = {
    {FlowGeometry::plane, 30, 50, 20, 0.28442, 0.58772, 1.2109},
    {FlowGeometry::plane, 20, 50, 20, 0.26425, 0.42516, 1.2196},
    {FlowGeometry::conical, 20, 50, 20, 0.07539, 0.21569, 1.2993},
    {FlowGeometry::conical, 29.5, 40, 16, 0.08940, 0.36830, 1.5308},
    {FlowGeometry::plane, 30, 50, 8.5, 0.46268, 0.63805, 1.3146},
};

// The shooting lands on the published s0, s_w and ff to 5 significant digits, plane and
// conical: the equations, the start on the axis and the wall condition psi_w = pi/2 + beta.
TEST(HopperFlowFactor, RadialStressFieldPrecisePoints) {
  for (const auto& p : kPrecisePoints) {
    const auto field =
        solve_radial_stress_field(p.g, p.theta * kDegree, p.delta * kDegree, p.phi_w * kDegree);
    ASSERT_TRUE(field.has_value()) << to_string(p.g) << " theta " << p.theta;
    EXPECT_NEAR(field->axis_stress, p.s0, 2e-5) << to_string(p.g) << " theta " << p.theta;
    EXPECT_NEAR(field->wall_stress, p.s_w, 2e-5) << to_string(p.g) << " theta " << p.theta;
    EXPECT_NEAR(field->flow_factor, p.ff, 2e-4) << to_string(p.g) << " theta " << p.theta;
  }
}

// The pine-like plane point: Enstad gives 1.3503 where the RSF gives 1.3146 (section 1.2).
TEST(HopperFlowFactor, EnstadPinePoint) {
  EXPECT_NEAR(enstad_flow_factor(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree),
              1.3503, 2e-4);
}

// The conical row of the table: (50, 20) at 10 and 20 deg, RSF/Enstad 1.35/1.36 and 1.30/1.29,
// and no admissible field at 30 deg, beyond the 26.1 deg limit.
TEST(HopperFlowFactor, ConicalRowAndBeyondTheLimit) {
  const double d = 50 * kDegree, w = 20 * kDegree;
  EXPECT_NEAR(solve_radial_stress_field(FlowGeometry::conical, 10 * kDegree, d, w)->flow_factor,
              1.35, 0.01);
  EXPECT_NEAR(enstad_flow_factor(FlowGeometry::conical, 10 * kDegree, d, w), 1.36, 0.01);
  EXPECT_NEAR(solve_radial_stress_field(FlowGeometry::conical, 20 * kDegree, d, w)->flow_factor,
              1.30, 0.01);
  EXPECT_NEAR(enstad_flow_factor(FlowGeometry::conical, 20 * kDegree, d, w), 1.29, 0.01);
  EXPECT_FALSE(solve_radial_stress_field(FlowGeometry::conical, 30 * kDegree, d, w).has_value());
}

// T4: conical delta = 40, phi_w = 16 at 29.5 deg: ff = 1.52 (Enstad) and 1.53 (RSF), against
// 1.5 read from Jenike's chart.
TEST(HopperFlowFactor, T4ConicalTutorialCase) {
  EXPECT_NEAR(enstad_flow_factor(FlowGeometry::conical, 29.5 * kDegree, 40 * kDegree, 16 * kDegree),
              1.52, 0.005);
  EXPECT_NEAR(
      solve_radial_stress_field(FlowGeometry::conical, 29.5 * kDegree, 40 * kDegree, 16 * kDegree)
          ->flow_factor,
      1.53, 0.005);
}

// The shooting residual falls with s0 in plane flow (single sign change, section 1.2), and the
// path that rises then falls back to psi_w is integrated to the wall, not cut at a crossing.
TEST(HopperFlowFactor, PlaneMismatchFallsWithAxisStress) {
  double previous = 1e9;
  for (double s0 = 1e-3; s0 < max_axis_stress(FlowGeometry::plane, 50 * kDegree); s0 *= 1.5) {
    const double f = radial_field_wall_mismatch(FlowGeometry::plane, 30 * kDegree, 50 * kDegree,
                                                20 * kDegree, s0);
    EXPECT_LE(f, previous + 1e-12) << "s0 " << s0;
    previous = f;
  }
}

// The passive field of section 1.3: it starts at the transition value, satisfies the slice
// equation d sigma1/dr = X sigma1/r - (X-1) rho g k (central differences) and turns radial,
// sigma1/(rho g r) -> (1 + sin delta) Y/(X-1), towards the outlet.
TEST(HopperFlowFactor, EnstadPassiveStressField) {
  const auto g = FlowGeometry::plane;
  const double t = 30 * kDegree, d = 50 * kDegree, w = 8.5 * kDegree, rho = 290, rg = rho * 9.81;
  const auto [x, y] = enstad_coefficients(g, t, d, w);
  const double k = (1 + std::sin(d)) * y / (x - 1);
  EXPECT_NEAR(enstad_passive_major_stress(g, t, d, w, rho, 0.6, 900.0, 0.6), 900.0, 1e-9);
  for (double r : {0.1, 0.3, 0.5}) {
    const double h = 1e-6;
    const double slope = (enstad_passive_major_stress(g, t, d, w, rho, 0.6, 900.0, r + h) -
                          enstad_passive_major_stress(g, t, d, w, rho, 0.6, 900.0, r - h)) / (2 * h);
    EXPECT_NEAR(slope, x * enstad_passive_major_stress(g, t, d, w, rho, 0.6, 900.0, r) / r -
                           (x - 1) * rg * k, 1e-3);
  }
  EXPECT_NEAR(enstad_passive_major_stress(g, t, d, w, rho, 0.6, 900.0, 1e-4) / (rg * 1e-4), k, 1e-3);
  const auto profile = enstad_passive_stress_profile(g, t, d, w, rho, 0.06, 0.6, 900.0, 10);
  ASSERT_EQ(profile.size(), 10u);
  EXPECT_NEAR(profile.front().radius, 0.06, 1e-12);
  EXPECT_NEAR(profile.back().major_stress, 900.0, 1e-9);
}

// Beyond the conical limit of a low-friction solid (delta 25, phi_w 20 deg: limit 29.5 deg)
// F(s0) jumps from the singular-line guard to negative values without a root: no field, not a
// spurious root and not an exception.
TEST(HopperFlowFactor, NoFieldAcrossAGuardJump) {
  EXPECT_FALSE(
      solve_radial_stress_field(FlowGeometry::conical, 50 * kDegree, 25 * kDegree, 20 * kDegree)
          .has_value());
  EXPECT_TRUE(
      solve_radial_stress_field(FlowGeometry::conical, 25 * kDegree, 25 * kDegree, 20 * kDegree)
          .has_value());
}

// A wall rougher than the solid and a semi-angle of 90 deg are refused, not computed.
TEST(HopperFlowFactor, RejectsImpossibleAngles) {
  EXPECT_THROW(enstad_flow_factor(FlowGeometry::plane, 30 * kDegree, 40 * kDegree, 45 * kDegree),
               std::invalid_argument);
  EXPECT_THROW(
      solve_radial_stress_field(FlowGeometry::plane, 90 * kDegree, 40 * kDegree, 10 * kDegree),
      std::invalid_argument);
}

}  // namespace
}  // namespace feedflow
