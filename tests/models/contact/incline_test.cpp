// Friction and rolling resistance on an inclined plate: one sphere, one plane contact, the seed's
// P-W parameters (Table 2: mu = 0.2, mu_r = 0.6), gravity tilted by the incline angle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "models/contact/contact_law.hpp"
#include "models/contact/hertz_normal.hpp"
#include "models/contact/hysteretic_nonlinear2.hpp"
#include "models/core/gravity.hpp"
#include "models/units/angle.hpp"
#include "tests/models/contact/single_contact_rig.hpp"
#include "tests/support/pine_table2.hpp"

namespace feedflow {
namespace {

constexpr double kDt = 1e-6;

DemContactParameters pine_wall() { return testing::pine_table2_particle_wall(); }  // seed Table 2, P-W

struct InclineRun {
  Vec3 x_mid = Vec3::Zero(), x_end = Vec3::Zero();  // position at half time and at the end
  Vec3 v_mid = Vec3::Zero(), v_end = Vec3::Zero();
  double w_end = 0.0;      // final rolling angular velocity about y [rad/s]
  long sign_flips = 0;     // sign changes of omega_y over the last 10 000 steps
};

// A pine sphere resting on the plane z = 0 with gravity tilted by `angle` about y (downhill is
// +x), started with speed v0 down the slope (rolling without slip unless locked), for `steps`.
template <class Law>
InclineRun on_incline(const Law& law, double angle, bool rotation_locked, double v0, long steps) {
  rig::Sphere s = rig::make_sphere(1.5e-3, 390.0);
  s.rotation_locked = rotation_locked;
  s.x = Vec3(0, 0, s.radius);
  s.v = Vec3(v0, 0, 0);
  if (!rotation_locked) s.w = Vec3(0, v0 / s.radius, 0);
  const Vec3 g = kGravity * Vec3(std::sin(angle), 0, -std::cos(angle));
  typename Law::History h{};
  InclineRun run;
  double w_prev = s.w.y();
  for (long n = 1; n <= steps; ++n) {
    rig::verlet_step(s, kDt, [&] {
      s.force += s.mass * g;
      const ContactInput in = rig::plane_contact(s, Vec3::Zero(), Vec3::UnitZ(), kDt);
      rig::apply(in, law.evaluate(in, h), s, nullptr, s.radius - in.overlap, 0.0);
    });
    if (n == steps / 2) {
      run.x_mid = s.x;
      run.v_mid = s.v;
    }
    if (n > steps - 10000 && (s.w.y() > 0) != (w_prev > 0)) ++run.sign_flips;
    w_prev = s.w.y();
  }
  run.x_end = s.x;
  run.v_end = s.v;
  run.w_end = s.w.y();
  return run;
}

using PineSliding = ContactLaw<HystereticNonlinear2, TangentialHistory<HandedOnStiffness>,
                               NoRolling, NoCohesion>;
using HertzMindlin = ContactLaw<HertzNormal, TangentialHistory<MindlinStiffness>, NoRolling,
                                NoCohesion>;

// A sphere that cannot roll (a sliding block) sticks 1.5 deg below atan(mu) and slides 1.5 deg
// above it with a = g (sin - mu cos) within 1 %, with the hysteretic law (k_t = k1) and with
// Hertz-Mindlin.
template <class Law>
void sticks_below_and_slides_above_the_friction_angle(const char* name) {
  const Law law(pine_wall());
  const double phi = std::atan(0.2);
  const long steps = 300000;  // 0.3 s
  const InclineRun stick = on_incline(law, phi - 1.5 * kDegree, true, 0.0, steps);
  const double creep = (stick.x_end - stick.x_mid).x();
  std::printf("%s: below, creep over the last 0.15 s %.2e m, final speed %.2e m/s\n", name,
              creep, stick.v_end.norm());
  EXPECT_LT(std::abs(creep), 1e-8);
  EXPECT_LT(stick.v_end.norm(), 1e-6);

  const double above = phi + 1.5 * kDegree;
  const InclineRun slide = on_incline(law, above, true, 0.0, steps);
  const double a = (slide.v_end - slide.v_mid).x() / (0.5 * steps * kDt);
  const double expected = kGravity * (std::sin(above) - 0.2 * std::cos(above));
  std::printf("%s: above, acceleration %.4f m/s^2, expected %.4f\n", name, a, expected);
  EXPECT_NEAR(a / expected, 1.0, 0.01);
}

TEST(Incline, HystereticSphereSticksBelowAndSlidesAboveAtanMu) {
  sticks_below_and_slides_above_the_friction_angle<PineSliding>("hysteretic");
}
TEST(Incline, HertzMindlinSphereSticksBelowAndSlidesAboveAtanMu) {
  sticks_below_and_slides_above_the_friction_angle<HertzMindlin>("hertz-mindlin");
}

template <class Rolling>
using PineRolling = ContactLaw<HystereticNonlinear2, TangentialHistory<HandedOnStiffness>,
                               Rolling, NoCohesion>;

// Plain cdt stops a sphere rolling down a 5 deg plate (0.05 m/s to a creep of ~2e-6 m/s) but
// then chatters: omega_y flips sign every few steps (what the clamped test must not show).
TEST(Incline, ConstantTorqueStopsTheSphereButChatters) {
  const InclineRun r =
      on_incline(PineRolling<RollingCdt>(pine_wall()), 5 * kDegree, false, 0.05, 200000);
  std::printf("cdt: final speed %.2e m/s, omega %.2e rad/s, %ld flips in 10000 steps\n",
              r.v_end.norm(), r.w_end, r.sign_flips);
  EXPECT_LT(r.v_end.norm(), 1e-4);
  EXPECT_GT(r.sign_flips, 1000);
}

// cdt_clamped stops it too and settles without chatter: omega_y keeps its sign (at most two
// flips in the last 10 000 steps). It keeps a creep omega = dt T/I (T the torque of the
// friction force, ~1.4e-3 rad/s here, vanishing with dt): the cap can stop rolling within a
// step but cannot hold a steady torque at omega = 0 (epsd2 can).
TEST(Incline, ClampedConstantTorqueSettlesWithoutChatter) {
  const InclineRun r =
      on_incline(PineRolling<RollingCdtClamped>(pine_wall()), 5 * kDegree, false, 0.05, 200000);
  std::printf("cdt_clamped: final speed %.2e m/s, omega %.2e rad/s, %ld flips, creep %.2e m\n",
              r.v_end.norm(), r.w_end, r.sign_flips, (r.x_end - r.x_mid).norm());
  EXPECT_LT(r.v_end.norm(), 1e-5);
  EXPECT_LE(r.sign_flips, 2);
  EXPECT_LT(std::abs(r.w_end), 3e-2);
}

// epsd2 (spring torque with a plastic cap) stops the sphere and holds it without chatter.
TEST(Incline, Epsd2StopsAndHoldsTheSphere) {
  const InclineRun r =
      on_incline(PineRolling<RollingEpsd2>(pine_wall()), 5 * kDegree, false, 0.05, 200000);
  std::printf("epsd2: final speed %.2e m/s, omega %.2e rad/s, %ld flips, creep %.2e m\n",
              r.v_end.norm(), r.w_end, r.sign_flips, (r.x_end - r.x_mid).norm());
  EXPECT_LT(r.v_end.norm(), 1e-5);
  EXPECT_LT((r.x_end - r.x_mid).norm(), 1e-7);
}

// Without rolling resistance the same sphere keeps rolling down: a = (5/7) g sin(theta).
TEST(Incline, WithoutRollingResistanceTheSphereRolls) {
  const InclineRun r = on_incline(PineSliding(pine_wall()), 5 * kDegree, false, 0.05, 200000);
  const double a = (r.v_end - r.v_mid).x() / 0.1;
  EXPECT_NEAR(a / (5.0 / 7.0 * kGravity * std::sin(5 * kDegree)), 1.0, 0.01);
}

}  // namespace
}  // namespace feedflow
