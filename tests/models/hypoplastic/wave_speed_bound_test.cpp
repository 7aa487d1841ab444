// The tangent wave-speed bound for the CFL step (models.md 5.2).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "models/hypoplastic/wave_speed_bound.hpp"
#include "tests/support/pine_table1.hpp"

namespace feedflow {
namespace {

using testing::kPine;

// Table 1 at p = 2 kPa, e = 0.71: M_b = 5.4e5 Pa, c = 43 m/s at 290 kg/m^3, and 5 mm cells give
// L/(sqrt3 c) ~ 7e-5 s (models.md 5.2).
TEST(HypoplasticWaveSpeed, Table1NumbersAt2kPa) {
  const Tensor3 t = -2e3 * Tensor3::Identity();
  EXPECT_NEAR(tangent_modulus_bound(kPine, t, 0.71), 5.4e5, 0.05e5);
  const double c = dilatational_wave_speed_bound(kPine, t, 0.71, 290.0);
  EXPECT_NEAR(c, 43.0, 0.5);
  EXPECT_NEAR(cfl_time_step(5e-3, c, 0.0, 1.0 / std::sqrt(3.0)), 7e-5, 0.5e-5);
  EXPECT_THROW(cfl_time_step(0.0, c, 0.0, 0.5), std::invalid_argument);
}

// The bound exceeds D:T°(D) for every unit symmetric D (Rayleigh quotient of the tangent,
// including the ||D|| term) at isotropic and sheared states, and the linear part's largest
// eigenvalue is 1.57 times the P-wave modulus M at an isotropic state (models.md 1.4).
TEST(HypoplasticWaveSpeed, BoundsTheTangent) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  Tensor3 sheared;
  sheared << -3e3, 500.0, 0.0, 500.0, -1.5e3, 200.0, 0.0, 200.0, -1e3;
  for (const Tensor3& t : {Tensor3(-2e3 * Tensor3::Identity()), sheared}) {
    const RateTerms r = rate_terms(kPine, t, 0.75);
    const double bound = tangent_modulus_bound(r);
    double largest = 0.0;
    for (int i = 0; i < 20000; ++i) {
      Tensor3 d;
      for (int a = 0; a < 3; ++a)
        for (int b = a; b < 3; ++b) d(a, b) = d(b, a) = normal(rng);
      d /= tensor_norm(d);
      largest = std::max(largest, d.cwiseProduct(stress_rate(r, d)).sum());
    }
    EXPECT_LE(largest, bound);
    EXPECT_GT(largest, 0.5 * bound);  // and it is not absurdly loose
  }
  const RateTerms iso = rate_terms(kPine, -2e3 * Tensor3::Identity(), 0.75);
  const double lambda = iso.stiffness * (iso.linear + 1.0 / 3.0);
  const double m = iso.stiffness * (iso.linear + 1.0 / 9.0);
  EXPECT_NEAR(lambda / m, 1.57, 0.005);
}

}  // namespace
}  // namespace feedflow
