// The cohesion parts and the reset on separation of the composed law (models.md 3.2-3.5).
#include <gtest/gtest.h>

#include <algorithm>

#include "models/contact/contact_law.hpp"
#include "models/contact/hysteretic_nonlinear1.hpp"
#include "models/contact/hysteretic_nonlinear2.hpp"

namespace feedflow {
namespace {

DemContactParameters pine_contact() {  // seed Table 2, P-P
  DemContactParameters p;
  p.alpha_prime = 20;
  p.chi = 2;
  p.a1 = 6e8;
  p.a2 = 5e4;
  p.a3 = 5;
  p.k_nc = 1e-4;
  p.c = 1e-7;
  p.restitution = 0.3;
  return p;
}

// Quasi-static cycle 0 -> 1e-4 m -> `end`; returns the normal force at the end.
template <class Law>
double cycle(const Law& law, typename Law::History& h, double end) {
  ContactInput in;
  in.effective_radius = 0.75e-3;
  in.effective_mass = 2.76e-6;
  in.dt = 1e-6;
  double f = 0.0;
  for (int i = 1; i <= 1000; ++i) {
    in.overlap = 1e-4 * i / 1000.0;
    in.normal_velocity = -1e-9;
    f = law.evaluate(in, h).normal_force;
  }
  for (int i = 1; i <= 1000; ++i) {
    in.overlap = 1e-4 + (end - 1e-4) * i / 1000.0;
    in.normal_velocity = 1e-9;
    f = law.evaluate(in, h).normal_force;
  }
  return f;
}

template <class Normal, class Cohesion>
using NormalOnly = ContactLaw<Normal, NoTangential, NoRolling, Cohesion>;

// nonlinear1 with k_nc: unloaded below delta_min the contact pulls with -K_nc A2 delta; with
// cohesion `none` the same history gives zero force (limitForce).
TEST(Cohesion, Nonlinear1PullsWithTheKncBranchOnlyWhenOn) {
  const double end = 2e-5;
  NormalOnly<HystereticNonlinear1, KncCohesion>::History h1{};
  const double pulled = cycle(NormalOnly<HystereticNonlinear1, KncCohesion>(pine_contact()), h1, end);
  EXPECT_NEAR(pulled, -1e-4 * 5e4 * end, 1e-6 * 5e4 * end);
  NormalOnly<HystereticNonlinear1, NoCohesion>::History h0{};
  EXPECT_EQ(cycle(NormalOnly<HystereticNonlinear1, NoCohesion>(pine_contact()), h0, end), 0.0);
}

// nonlinear2 with k_nc (the [I] extension): attractive below delta0, never beyond -k_c delta
// (here it has reached the line).
TEST(Cohesion, Nonlinear2AttractionIsBoundedByTheKncLine) {
  const double end = 2e-5;
  NormalOnly<HystereticNonlinear2, KncCohesion>::History h{};
  const double f = cycle(NormalOnly<HystereticNonlinear2, KncCohesion>(pine_contact()), h, end);
  EXPECT_LT(f, 0.0);
  EXPECT_GE(f, -1e-4 * 5e4 * end * (1 + 1e-6));  // 1e-6: the dashpot at v_n = 1e-9 m/s
}

// An opened contact (overlap <= 0) zeroes its history and exerts nothing: a re-formed contact
// starts again on the virgin curve.
TEST(Cohesion, OpeningResetsTheHistory) {
  using Law = ContactLaw<HystereticNonlinear2, TangentialHistory<HandedOnStiffness>, RollingEpsd2>;
  const Law law(pine_contact());
  Law::History h{};
  cycle(law, h, 5e-5);
  EXPECT_TRUE(std::any_of(h.begin(), h.end(), [](double x) { return x != 0.0; }));
  ContactInput open;
  open.overlap = -1e-6;
  const ContactOutput out = law.evaluate(open, h);
  EXPECT_EQ(out.normal_force, 0.0);
  EXPECT_TRUE(std::all_of(h.begin(), h.end(), [](double x) { return x == 0.0; }));
}

}  // namespace
}  // namespace feedflow
