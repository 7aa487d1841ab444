// Drum: Froude number and critical speed (T9), fill geometry, the seed's regime labels, the
// full-bed centrifuging and no-slip criteria, and the rolling-layer angle of repose (section 4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "models/drum/drum_regime.hpp"
#include "models/drum/rolling_layer.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

Drum seed_drum(double rpm) {
  Drum d;
  d.diameter = 0.145;
  d.length = 0.202;
  d.fill_fraction = 0.5;
  d.speed = rpm * kRpm;
  return d;
}

// T9: n_c = 111.1 rpm and Fr(20 rpm) = 0.0324 for the seed drum; Fr = (n/n_c)^2.
TEST(DrumRegime, T9CriticalSpeedAndFroude) {
  EXPECT_NEAR(drum_critical_speed(0.145) / kRpm, 111.1, 0.05);
  EXPECT_NEAR(drum_froude(0.145, 20 * kRpm), 0.0324, 0.00005);
  EXPECT_NEAR(drum_froude(0.145, 300 * kRpm), 7.29, 0.005);
  EXPECT_NEAR(drum_froude(0.145, drum_critical_speed(0.145)), 1.0, 1e-12);
}

// Fill segment: half fill is a half disc (eps = 90 deg, L_c = R, r_g = 4R/(3 pi)); the root
// reproduces f for another fill.
TEST(DrumRegime, FillSegmentGeometry) {
  const auto half = fill_segment(0.145, 0.5);
  EXPECT_NEAR(half.half_angle, std::numbers::pi / 2, 1e-10);
  EXPECT_NEAR(half.half_chord, 0.0725, 1e-12);
  EXPECT_NEAR(half.centroid_radius, 4 * 0.0725 / (3 * std::numbers::pi), 1e-12);
  const double eps = fill_segment(0.145, 0.3).half_angle;
  EXPECT_NEAR((2 * eps - std::sin(2 * eps)) / (2 * std::numbers::pi), 0.3, 1e-12);
  EXPECT_THROW(fill_segment(0.145, 1.0), std::invalid_argument);
}

// The seed's labels with the default (calibrated, not Mellmann) thresholds: 10 and 20 rpm roll,
// 50 rpm cascades, 300 rpm centrifuges; a crawl slumps.
TEST(DrumRegime, SeedLabels) {
  const DrumRegimeThresholds t;
  EXPECT_EQ(assess_drum_regime(seed_drum(10), t).regime, DrumRegime::Rolling);
  EXPECT_EQ(assess_drum_regime(seed_drum(20), t).regime, DrumRegime::Rolling);
  EXPECT_EQ(assess_drum_regime(seed_drum(50), t).regime, DrumRegime::Cascading);
  EXPECT_EQ(assess_drum_regime(seed_drum(300), t).regime, DrumRegime::Centrifuging);
  EXPECT_EQ(assess_drum_regime(seed_drum(0.5), t).regime, DrumRegime::Slumping);
  EXPECT_EQ(assess_drum_regime(seed_drum(80), t).regime, DrumRegime::Cataracting);
}

// Full bed centrifuges at Fr >= 1/sqrt(1 - f) = 1.41, i.e. 132 rpm at half fill: 120 rpm spins
// the outer layer only, 300 rpm the whole bed.
TEST(DrumRegime, FullBedCentrifugingCriterion) {
  const DrumRegimeThresholds t;
  const auto a120 = assess_drum_regime(seed_drum(120), t);
  EXPECT_NEAR(a120.full_bed_centrifuging_froude, std::sqrt(2.0), 1e-12);
  EXPECT_EQ(a120.regime, DrumRegime::Centrifuging);
  EXPECT_FALSE(a120.full_bed_centrifuges);
  EXPECT_TRUE(assess_drum_regime(seed_drum(300), t).full_bed_centrifuges);
  EXPECT_NEAR(std::sqrt(std::sqrt(2.0)) * drum_critical_speed(0.145) / kRpm, 132.1, 0.1);
}

// No slip needs tan(phi_w) > (r_g/R) sin(beta_d): 0.424 sin(25 deg) = 0.179 (10.2 deg); the
// seed's 20 deg shell holds, 5 deg slips, and without a wall angle nothing is claimed.
TEST(DrumRegime, NoSlipWallCriterion) {
  Drum d = seed_drum(20);
  const DrumRegimeThresholds t;
  EXPECT_FALSE(assess_drum_regime(d, t, 25 * kDegree).wall_slips.has_value());
  d.wall_friction_angle = 20 * kDegree;
  const auto holds = assess_drum_regime(d, t, 25 * kDegree);
  EXPECT_NEAR(holds.no_slip_friction, 4 / (3 * std::numbers::pi) * std::sin(25 * kDegree), 1e-12);
  EXPECT_FALSE(*holds.wall_slips);
  d.wall_friction_angle = 5 * kDegree;
  EXPECT_TRUE(*assess_drum_regime(d, t, 25 * kDegree).wall_slips);
}

RollingLayerModel glass_beads() {
  RollingLayerModel m;
  m.rheology = {std::tan(20.9 * kDegree), std::tan(32.76 * kDegree), 0.279, 0.5e-3, 0.6};
  m.layer_fraction = 0.2;
  return m;
}

// Section 4 glass-bead example: AoR = 22.1 / 23.1 / 24.7 / 25.8 deg at 5 / 10 / 20 / 30 rpm.
TEST(RollingLayer, GlassBeadExample) {
  const double expected[][2] = {{5, 22.1}, {10, 23.1}, {20, 24.7}, {30, 25.8}};
  for (const auto& [rpm, aor] : expected) {
    const auto s = rolling_angle_of_repose(seed_drum(rpm), glass_beads());
    EXPECT_NEAR(s.angle_of_repose / kDegree, aor, 0.05) << rpm << " rpm";
  }
}

// Trend: the AoR rises with rpm, starts just above theta1 and stays below theta2; end-wall
// friction raises it by mu_ew delta_L/W.
TEST(RollingLayer, AngleRisesWithSpeedAndEndWalls) {
  double previous = std::atan(glass_beads().rheology.mu_s);
  for (double rpm = 1; rpm <= 40; rpm += 3) {
    const double a = rolling_angle_of_repose(seed_drum(rpm), glass_beads()).angle_of_repose;
    EXPECT_GT(a, previous) << rpm;
    EXPECT_LT(a, 32.76 * kDegree);
    previous = a;
  }
  auto walls = glass_beads();
  walls.end_wall_friction = 0.5;
  const auto plain = rolling_angle_of_repose(seed_drum(20), glass_beads());
  const auto with = rolling_angle_of_repose(seed_drum(20), walls);
  EXPECT_GT(with.angle_of_repose, plain.angle_of_repose + 0.5 * kDegree);
  EXPECT_NEAR(std::tan(with.angle_of_repose),
              friction_coefficient(walls.rheology, with.inertial_number) +
                  0.5 * with.layer_thickness / 0.202, 1e-10);
}

}  // namespace
}  // namespace feedflow
