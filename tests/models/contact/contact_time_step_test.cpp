// Stable time step (models.md 5.1): the Rayleigh and Hertz numbers of the spec, the pine step
// and its justification, the hysteretic spring slopes it is built on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "models/contact/contact_law_registry.hpp"
#include "models/contact/contact_time_step.hpp"
#include "tests/support/pine_table2.hpp"

namespace feedflow {
namespace {

DemContactParameters pine_contact(double friction, double rolling) {  // seed Table 2
  return testing::pine_table2_contact(friction, rolling);
}

DemParameters pine_parameters() {
  return {{1.5e-3, 390.0}, pine_contact(0.5, 0.8), pine_contact(0.2, 0.6)};
}

// T_R = 1.62e-4 s for Table 2 (models.md 5.1).
TEST(ContactTimeStep, RayleighTimeOfPine) {
  EXPECT_NEAR(rayleigh_time(1.5e-3, 390.0, 1e6, 0.3), 1.62e-4, 0.005e-4);
}

// LIGGGHTS' Hertz time for Table 2: 6.7e-4, 4.2e-4, 3.4e-4 s at v_max = 0.1, 1, 3 m/s.
TEST(ContactTimeStep, HertzTimeOfPine) {
  const double m = 390.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(1.5e-3, 3);
  const double e_star = effective_youngs_modulus(1e6, 0.3);
  EXPECT_NEAR(hertz_collision_time(m, 0.75e-3, e_star, 0.2), 6.7e-4, 0.05e-4);
  EXPECT_NEAR(hertz_collision_time(m, 0.75e-3, e_star, 2.0), 4.2e-4, 0.05e-4);
  EXPECT_NEAR(hertz_collision_time(m, 0.75e-3, e_star, 6.0), 3.4e-4, 0.05e-4);
}

// The nonlinear2 unloading slope at delta_max = 1e-4 m after a virgin loading is 1.2e3 N/m and
// the loading slope 2 alpha A2 delta = 200 N/m (models.md 5.1); k_t = A2 before any reversal.
TEST(ContactTimeStep, HystereticSpringSlopes) {
  using Law = ContactLaw<HystereticNonlinear2, TangentialHistory<HandedOnStiffness>, RollingCdt>;
  const Law law(pine_contact(0.5, 0.8));
  Law::History h{};
  ContactInput in;
  in.overlap = 1e-4;
  in.normal_velocity = -1e-3;
  in.effective_radius = 0.75e-3;
  in.effective_mass = 2.76e-6;
  in.effective_inertia = 1e-12;
  in.dt = 1e-6;
  law.evaluate(in, h);
  const ContactStiffness k = law.stiffness(in, h);
  EXPECT_NEAR(k.normal, 1.194e3, 0.01e3);
  EXPECT_DOUBLE_EQ(k.tangential, 5e4);
  EXPECT_EQ(k.rolling, 0.0);
}

// Pine with the seed's law: the P-P tangential spring k_t = k1 = A1 delta + A2 at 0.1 R limits
// the step to period/20 = 7.5e-7 s (the seed ran at 1e-6 s, period/15), far below the Rayleigh
// (3.2e-5 s) and Hertz (8.4e-5 s) bounds; the justification names it.
TEST(ContactTimeStep, PineStepIsLimitedByTheTangentialSpring) {
  const ContactLawChoice seed;
  const StableTimeStep dt = stable_time_step(
      pine_parameters(), design_springs(pine_parameters(), seed, seed, 0.1), TimeStepSettings{});
  std::printf("%s\n", dt.justification.c_str());
  const double m_t = 2.0 / 7.0 * 0.5 * 390.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(1.5e-3, 3);
  const double k1 = 6e8 * 1.5e-4 + 5e4;
  EXPECT_NEAR(dt.value, 2 * std::numbers::pi * std::sqrt(m_t / k1) / 20, 1e-12);
  EXPECT_NE(dt.justification.find("stiffest spring"), std::string::npos);
  EXPECT_NE(dt.justification.find("P-P tangential"), std::string::npos);
}

// With a soft law and a loose spring criterion the Rayleigh time limits, and the text says so.
TEST(ContactTimeStep, RayleighLimitsAHertzLawWithFewStepsPerPeriod) {
  const ContactLawChoice hertz = choose_contact_law("hertz", "mindlin", "cdt", "none");
  TimeStepSettings settings;
  settings.steps_per_period = 5;
  const StableTimeStep dt = stable_time_step(
      pine_parameters(), design_springs(pine_parameters(), hertz, hertz, 0.1), settings);
  std::printf("%s\n", dt.justification.c_str());
  EXPECT_NEAR(dt.value, 0.2 * 1.621e-4, 0.005e-5);
  EXPECT_EQ(dt.justification.find("dt = 3.24e-05 s from the Rayleigh time"), 0u);
}

}  // namespace
}  // namespace feedflow
