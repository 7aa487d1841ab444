// Pouliquen h_stop law, flow rule, chute sizing, mu(I) conversions, cohesive slope and the
// two-measurement inversion (reduced_models.md section 3, test vector T8).
#include <gtest/gtest.h>

#include <cmath>

#include "models/chute/cohesive_slope.hpp"
#include "models/chute/mu_i_rheology.hpp"
#include "models/chute/pouliquen_law.hpp"
#include "models/chute/stop_thickness_inversion.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

constexpr double kBeadD = 0.5e-3;

// T8 glass beads: theta1 = 20.9, theta2 = 32.76 deg, I0 = 0.279, beta = 0.136, phi = 0.6.
PouliquenLaw beads() {
  PouliquenLaw law;
  law.theta1 = 20.9 * kDegree;
  law.theta2 = 32.76 * kDegree;
  law.length = length_from_i0(0.279, 0.136, kBeadD, 0.6, 25 * kDegree, FroudeConvention::SqrtGH);
  law.beta = 0.136;
  return law;
}

// T8: matching mu(I)-Bagnold to the flow rule at 25 deg gives L = 1.65 d.
TEST(PouliquenLaw, T8LengthMatchedAt25Degrees) {
  EXPECT_NEAR(beads().length / kBeadD, 1.65, 0.005);
  // The inverse conversions are consistent.
  EXPECT_NEAR(i0_from_pouliquen(0.136, beads().length, kBeadD, 0.6, 25 * kDegree,
                                FroudeConvention::SqrtGH), 0.279, 1e-12);
  EXPECT_NEAR(beta_from_i0(0.279, beads().length, kBeadD, 0.6, 25 * kDegree,
                           FroudeConvention::SqrtGH), 0.136, 1e-12);
}

// T8: h_stop = 8.9 / 1.73 / 0.62 mm at 22 / 25 / 28 deg.
TEST(PouliquenLaw, T8StoppingThicknessOfGlassBeads) {
  EXPECT_NEAR(stopping_thickness(beads(), 22 * kDegree).thickness * 1e3, 8.9, 0.1);
  EXPECT_NEAR(stopping_thickness(beads(), 25 * kDegree).thickness * 1e3, 1.73, 0.01);
  EXPECT_NEAR(stopping_thickness(beads(), 28 * kDegree).thickness * 1e3, 0.62, 0.01);
}

// T8: u(h = 5 mm, 25 deg) = 0.0869 m/s both from the Bagnold profile and from the flow rule;
// the sqrt(g h cos) convention with the same constants gives 4.8 % less.
TEST(PouliquenLaw, T8MeanVelocityFromMuIAndFromFlowRule) {
  const auto rheology =
      mu_i_from_pouliquen(beads(), kBeadD, 0.6, 25 * kDegree, FroudeConvention::SqrtGH);
  EXPECT_NEAR(bagnold_inertial_number(rheology, 25 * kDegree), 0.133, 0.0005);
  EXPECT_NEAR(bagnold_mean_velocity(rheology, 5e-3, 25 * kDegree), 0.0869, 0.0001);
  EXPECT_NEAR(flow_rule_velocity(beads(), 5e-3, 25 * kDegree), 0.0869, 0.0001);
  EXPECT_NEAR(flow_rule_velocity(beads(), 5e-3, 25 * kDegree) * std::sqrt(std::cos(25 * kDegree)),
              0.0827, 0.0001);
}

// Section 3 example: theta1 = 27, theta2 = 40 deg, L = 10 mm gives 48.6 mm at 29.5 deg and
// 3.5 mm at 37 deg (the seed's ordering: the thicker deposit at the shallower angle).
TEST(PouliquenLaw, Section3PineExample) {
  const PouliquenLaw law{27 * kDegree, 40 * kDegree, 10e-3};
  EXPECT_NEAR(stopping_thickness(law, 29.5 * kDegree).thickness * 1e3, 48.6, 0.05);
  EXPECT_NEAR(stopping_thickness(law, 37 * kDegree).thickness * 1e3, 3.5, 0.05);
}

// Trend: h_stop falls strictly with the angle across (theta1, theta2).
TEST(PouliquenLaw, StoppingThicknessFallsWithAngle) {
  const auto law = beads();
  double previous = stopping_thickness(law, 21.0 * kDegree).thickness;
  for (double a = 21.5; a < 32.7; a += 0.5) {
    const double h = stopping_thickness(law, a * kDegree).thickness;
    EXPECT_LT(h, previous) << a;
    previous = h;
  }
}

// The two limits are explicit outcomes with words, not numbers to misread.
TEST(PouliquenLaw, OutcomesOutsideTheBandAreSaid) {
  const auto above = stopping_thickness(beads(), 35 * kDegree);
  EXPECT_EQ(above.outcome, DepositOutcome::NoDepositAboveTheta2);
  EXPECT_EQ(above.thickness, 0.0);
  EXPECT_NE(above.words.find("no deposit"), std::string::npos);
  const auto below = stopping_thickness(beads(), 20 * kDegree);
  EXPECT_EQ(below.outcome, DepositOutcome::NeverFlowsBelowTheta1);
  EXPECT_TRUE(std::isinf(below.thickness));
  EXPECT_NE(below.words.find("never flows"), std::string::npos);
  EXPECT_THROW(flow_rule_froude(beads(), 1e-3, 35 * kDegree), std::invalid_argument);
  EXPECT_THROW(stopping_thickness(PouliquenLaw{30 * kDegree, 20 * kDegree, 1e-3}, 25 * kDegree),
               std::invalid_argument);
}

// The 1999 exponential form: tan theta_stop(h) inverts exactly, and h -> 0 at theta2.
TEST(PouliquenLaw, ExponentialFormInvertsItsDefinition) {
  const PouliquenExponentialLaw law{20.9 * kDegree, 32.76 * kDegree, 1.5e-3};
  const double h = stopping_thickness(law, 25 * kDegree).thickness;
  const double t1 = std::tan(law.theta1), t2 = std::tan(law.theta2);
  EXPECT_NEAR(t1 + (t2 - t1) * std::exp(-h / law.decay_length), std::tan(25 * kDegree), 1e-12);
  EXPECT_EQ(stopping_thickness(law, 33 * kDegree).outcome, DepositOutcome::NoDepositAboveTheta2);
}

// Chute sizing: the closed form (Gamma = 0) and the Brent root (Gamma > 0) carry the asked q.
TEST(PouliquenLaw, ChuteSizingCarriesTheFlowRate) {
  const double q = 2e-3, angle = 25 * kDegree;
  const double h = thickness_for_flow_rate(beads(), q, angle);
  EXPECT_NEAR(h * flow_rule_velocity(beads(), h, angle), q, 1e-12);
  PouliquenLaw sand = beads();
  sand.beta = 0.65;
  sand.gamma = 0.77;
  const double hs = thickness_for_flow_rate(sand, q, angle);
  EXPECT_NEAR(hs * flow_rule_velocity(sand, hs, angle), q, 1e-10);
  EXPECT_GT(hs, sand.gamma / sand.beta * stopping_thickness(sand, angle).thickness);
}

// The depth-averaged friction law: tan(theta) = mu_dyn(h, Fr) is the flow rule, tan(theta) =
// mu_stop(h) is h_stop, and with Gamma = 0 mu_dyn is mu(I) of I = (5/2) d u/(h sqrt(g h)).
TEST(PouliquenLaw, BasalFrictionEncodesFlowRuleAndStop) {
  const auto law = beads();
  const double angle = 25 * kDegree, h = 5e-3;
  const double fr = flow_rule_froude(law, h, angle);
  EXPECT_NEAR(basal_friction(law, h, fr), std::tan(angle), 1e-12);
  const double hs = stopping_thickness(law, angle).thickness;
  EXPECT_NEAR(basal_friction_at_rest(law, hs), std::tan(angle), 1e-12);
  const MuIRheology depth_averaged{std::tan(law.theta1), std::tan(law.theta2),
                                   2.5 * law.beta * kBeadD / law.length, kBeadD, 1.0};
  const double u = 0.3;
  const double i = depth_averaged_inertial_number(kBeadD, u, h);
  EXPECT_NEAR(basal_friction(law, h, u / std::sqrt(kGravity * h)),
              friction_coefficient(depth_averaged, i), 1e-12);
}

// Mohr-Coulomb infinite slope: the reference's magnitude check (c = 100 Pa, phi = 30 deg,
// rho_b = 290: 0.31 m at 37 deg, a vertical depth) and its limits.
TEST(CohesiveSlope, InfiniteSlopeMagnitudeAndLimits) {
  const CohesiveSlope slope{100.0, 30 * kDegree, 290.0};
  const auto stop = cohesive_stopping_depth(slope, 37 * kDegree);
  EXPECT_NEAR(stop.vertical_depth, 0.3128, 0.0005);
  EXPECT_NEAR(stop.normal.thickness, stop.vertical_depth * std::cos(37 * kDegree), 1e-12);
  EXPECT_EQ(cohesive_stopping_depth(slope, 29 * kDegree).normal.outcome,
            DepositOutcome::NeverFlowsBelowTheta1);
  EXPECT_EQ(cohesive_stopping_depth({0.0, 30 * kDegree, 290.0}, 37 * kDegree).normal.outcome,
            DepositOutcome::NoDepositAboveTheta2);
}

// Hybrid: c = 0 is Pouliquen's law; L -> 0 is the infinite slope (normal thickness, phi =
// theta1); cohesion thickens the deposit and keeps one above theta2.
TEST(CohesiveSlope, HybridReducesToBothParents) {
  const PouliquenLaw law{27 * kDegree, 40 * kDegree, 10e-3};
  EXPECT_NEAR(hybrid_stopping_thickness(law, 0.0, 290.0, 30 * kDegree).thickness,
              stopping_thickness(law, 30 * kDegree).thickness, 1e-15);
  PouliquenLaw thin = law;
  thin.length = 1e-15;
  EXPECT_NEAR(hybrid_stopping_thickness(thin, 10.0, 290.0, 33 * kDegree).thickness,
              cohesive_stopping_depth({10.0, 27 * kDegree, 290.0}, 33 * kDegree).normal.thickness,
              1e-9);
  EXPECT_GT(hybrid_stopping_thickness(law, 10.0, 290.0, 30 * kDegree).thickness,
            stopping_thickness(law, 30 * kDegree).thickness);
  EXPECT_EQ(hybrid_stopping_thickness(law, 10.0, 290.0, 41 * kDegree).outcome,
            DepositOutcome::Deposit);
}

// Inversion: the section 3 example's two deposits give back theta2 = 40 deg and L = 10 mm;
// thicknesses rising with angle are refused.
TEST(StopThicknessInversion, RecoversTheta2AndLength) {
  const PouliquenLaw truth{27 * kDegree, 40 * kDegree, 10e-3};
  const StopMeasurement a{29.5 * kDegree, stopping_thickness(truth, 29.5 * kDegree).thickness};
  const StopMeasurement b{37 * kDegree, stopping_thickness(truth, 37 * kDegree).thickness};
  const auto law = invert_stopping_thickness(27 * kDegree, a, b);
  EXPECT_NEAR(law.theta2 / kDegree, 40.0, 1e-9);
  EXPECT_NEAR(law.length, 10e-3, 1e-12);
  EXPECT_THROW(
      invert_stopping_thickness(27 * kDegree, {29.5 * kDegree, 3e-3}, {37 * kDegree, 40e-3}),
      std::invalid_argument);
}

}  // namespace
}  // namespace feedflow
