// The implicit Coulomb stopping step of the L1 chute model (implicit_friction.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "models/chute/implicit_friction.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

// The new speed solves u + k mu(h, u/sqrt(g h)) = u* on both branches of the law, with
// Gamma = 0 (glass-bead like) and Gamma > beta (angular sand, mu at rest on the dynamic branch).
TEST(ImplicitFriction, NewSpeedSolvesTheBackwardEulerEquation) {
  for (const PouliquenLaw law : {PouliquenLaw{27 * kDegree, 40 * kDegree, 10e-3, 0.136, 0.0},
                                 PouliquenLaw{27 * kDegree, 40 * kDegree, 10e-3, 0.65, 0.77}}) {
    const ImplicitFriction f(law);
    for (double h : {2e-3, 0.05, 0.4}) {
      for (double k : {1e-3, 0.1, 2.0}) {
        for (double u_star : {0.01, 0.3, 3.0, 30.0}) {
          const double u = f.speed_after(h, u_star, k);
          if (u == 0.0) {  // held: the impulse at rest covers u*
            EXPECT_LE(u_star, k * basal_friction(law, h, 0.0) * (1 + 1e-12));
            continue;
          }
          const double mu = basal_friction(law, h, u / std::sqrt(kGravity * h));
          EXPECT_NEAR(u + k * mu, u_star, 1e-12 * u_star) << h << " " << k << " " << u_star;
        }
      }
    }
  }
}

// A steady uniform layer is a fixed point at the flow rule for any step: u* = u + dt g sin
// returns u exactly when u is the flow-rule speed, even for dt = 1 s.
TEST(ImplicitFriction, FlowRuleIsAFixedPointAtAnyStep) {
  const PouliquenLaw law{27 * kDegree, 40 * kDegree, 10e-3, 0.136, 0.0};
  const ImplicitFriction f(law);
  const double angle = 33 * kDegree, h = 0.03;
  const double u = flow_rule_velocity(law, h, angle);
  for (double dt : {1e-4, 1e-2, 1.0}) {
    const double u_star = u + dt * kGravity * std::sin(angle);
    EXPECT_NEAR(f.speed_after(h, u_star, dt * kGravity * std::cos(angle)), u, 1e-12) << dt;
  }
}

// Coulomb friction (theta1 == theta2) removes k tan(theta1) and stops at zero; mu_stop matches
// the law's basal_friction_at_rest.
TEST(ImplicitFriction, CoulombLawAndFrictionAtRest) {
  const ImplicitFriction coulomb({30 * kDegree, 30 * kDegree, 0.0, 0.136, 0.0});
  EXPECT_NEAR(coulomb.speed_after(0.1, 1.0, 0.5), 1.0 - 0.5 * std::tan(30 * kDegree), 1e-15);
  EXPECT_EQ(coulomb.speed_after(0.1, 0.2, 0.5), 0.0);
  const PouliquenLaw law{27 * kDegree, 40 * kDegree, 10e-3, 0.136, 0.0};
  EXPECT_NEAR(ImplicitFriction(law).at_rest(0.02), basal_friction_at_rest(law, 0.02), 1e-15);
}

}  // namespace
}  // namespace feedflow
