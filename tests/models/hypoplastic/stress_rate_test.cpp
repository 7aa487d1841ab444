// The G-B and von Wolffersdorff rate laws against the numbers of models.md 1.2-1.4.
#include <gtest/gtest.h>

#include <cmath>

#include "models/hypoplastic/stress_rate.hpp"
#include "models/hypoplastic/stress_terms.hpp"
#include "models/material/bulk_compressibility.hpp"
#include "tests/support/pine_table1.hpp"

namespace feedflow {
namespace {

using testing::kPine;

Tensor3 isotropic(double p) { return -p * Tensor3::Identity(); }
Tensor3 triaxial(double axial, double lateral) {  // compressive magnitudes
  return Eigen::Vector3d(-lateral, -lateral, -axial).asDiagonal();
}

// Table 1 derived constants of models.md 1.4: c1, c2, h_i and the vW denominator.
TEST(HypoplasticRate, Table1DerivedConstants) {
  const auto& c = kPine.constants;
  EXPECT_NEAR(c.sin_phi_c, 0.73491, 5e-6);
  EXPECT_NEAR(c.c1, 1.88740, 5e-6);
  EXPECT_NEAR(c.c2, 1.90579, 5e-6);
  EXPECT_NEAR(c.h_i, 0.263734, 5e-7);
  EXPECT_NEAR(c.vw_denominator, 2.81847, 5e-6);
  EXPECT_DOUBLE_EQ(c.vw_a, c.c1);  // models.md 1.2 item 5 note
}

// f_s and the constrained modulus M at p = 1 kPa, e = 0.71 (models.md 1.4 table: 3.76e5, 1.47e5).
TEST(HypoplasticRate, StiffnessFactorAndModulusAt1kPa) {
  const RateTerms r = gudehus_bauer_terms(kPine, isotropic(1e3), 0.71);
  EXPECT_NEAR(r.stiffness, 3.76e5, 0.005e5);
  EXPECT_NEAR(r.linear, 1.0 / (kPine.constants.c1 * kPine.constants.c1), 1e-12);  // a1 = 1/c1
  const double m = r.stiffness * (r.linear + 1.0 / 9.0);
  EXPECT_NEAR(m, 1.47e5, 0.005e5);
  // Oedometric D = diag(0,0,-1) without the N term gives the same M.
  Tensor3 d = Tensor3::Zero();
  d(2, 2) = -1.0;
  RateTerms linear_only = r;
  linear_only.nonlinear.setZero();
  EXPECT_NEAR(-stress_rate(linear_only, d)(2, 2), m, 1e-9 * m);
  // 100 Pa at e_c and 10 kPa at e_c (same table): f_s = 6.26e4, 1.96e6.
  EXPECT_NEAR(gudehus_bauer_terms(kPine, isotropic(100.0), limit_void_ratios(kPine.parameters, 100.0).e_c)
                  .stiffness, 6.26e4, 0.005e4);
  EXPECT_NEAR(gudehus_bauer_terms(kPine, isotropic(1e4), limit_void_ratios(kPine.parameters, 1e4).e_c)
                  .stiffness, 1.96e6, 0.005e6);
}

// Lode convention: triaxial compression has cos3theta = -1 (a1 = 1/c1), extension +1.
TEST(HypoplasticRate, LodeAngleConvention) {
  const Tensor3 tc = triaxial(3e3, 1e3), te = triaxial(1e3, 3e3);
  EXPECT_NEAR(normalized_stress(tc, tc.trace()).cos3theta, -1.0, 1e-12);
  EXPECT_NEAR(normalized_stress(te, te.trace()).cos3theta, 1.0, 1e-12);
  const RateTerms r = gudehus_bauer_terms(kPine, tc, 0.8);
  EXPECT_NEAR(r.linear, 1.0 / (kPine.constants.c1 * kPine.constants.c1), 1e-12);
}

// The rate is homogeneous of degree one in D (rate independence of hypoplasticity).
TEST(HypoplasticRate, HomogeneousOfDegreeOneInStretching) {
  Tensor3 d;
  d << -1.0, 0.3, 0.1, 0.3, 0.4, -0.2, 0.1, -0.2, 0.2;
  const Tensor3 t = triaxial(2.5e3, 1.2e3);
  for (const auto variant : {HypoplasticVariant::gudehus_bauer, HypoplasticVariant::von_wolffersdorff}) {
    const auto m = make_hypoplastic_model(loblolly_pine_table1(), variant);
    const Tensor3 r1 = stress_rate(m, t, 0.8, d), r2 = stress_rate(m, t, 0.8, 2.0 * d);
    EXPECT_LT((r2 - 2.0 * r1).norm(), 1e-12 * r2.norm());
    EXPECT_LT((r1 - r1.transpose()).norm(), 1e-12 * r1.norm());  // symmetric
  }
}

// models.md 1.2 consistency: at e = e_i, isotropic D = -eps I gives T° = -eps f_s h_i I, for
// both variants (their stiffness normalisations h_i and the vW denominator).
TEST(HypoplasticRate, IsotropicRateOnUpperBoundIsCompressionLaw) {
  const double p = 2e3;
  const double e_i = limit_void_ratios(kPine.parameters, p).e_i;
  const Tensor3 d = -Tensor3::Identity();
  const RateTerms gb = gudehus_bauer_terms(kPine, isotropic(p), e_i);
  const Tensor3 rate = stress_rate(gb, d);
  EXPECT_LT((rate + gb.stiffness * kPine.constants.h_i * Tensor3::Identity()).norm(),
            1e-10 * rate.norm());
  // Both variants give the same rate there: d(tr T)/de of the compression law.
  const auto vw = make_hypoplastic_model(loblolly_pine_table1(), HypoplasticVariant::von_wolffersdorff);
  const Tensor3 rate_vw = stress_rate(vw, isotropic(p), e_i, d);
  EXPECT_LT((rate_vw - rate).norm(), 1e-10 * rate.norm());
}

// Von Wolffersdorff: F = 1 in triaxial compression, so the linear factor is F^2 = 1.
TEST(HypoplasticRate, VonWolffersdorffFactorIsOneInCompression) {
  const auto vw = make_hypoplastic_model(loblolly_pine_table1(), HypoplasticVariant::von_wolffersdorff);
  const RateTerms r = von_wolffersdorff_terms(vw, triaxial(4e3, 1e3), 0.8);
  EXPECT_NEAR(r.linear, 1.0, 1e-12);
  EXPECT_NEAR(r.projection, vw.constants.vw_a * vw.constants.vw_a, 1e-12);
}

// Zero and tensile stress: finite rates, compression-law rate when compressed, zero otherwise.
TEST(HypoplasticRate, ZeroAndTensileStressGiveFiniteRates) {
  const Tensor3 d_compress = -Tensor3::Identity(), d_extend = Tensor3::Identity();
  for (const Tensor3& t : {Tensor3(Tensor3::Zero()), Tensor3(5.0 * Tensor3::Identity()),
                           Tensor3(triaxial(-1.0, 2e-4))}) {
    const RateTerms r = gudehus_bauer_terms(kPine, t, 0.8);
    EXPECT_TRUE(r.near_zero);
    EXPECT_TRUE(stress_rate(r, d_compress).allFinite());
    EXPECT_LT(stress_rate(r, d_compress)(0, 0), 0.0);  // compression builds pressure
    EXPECT_EQ(stress_rate(r, d_extend).norm(), 0.0);   // extension leaves it at zero
  }
  // Looser than e_i0 at zero stress: no stiffness at all (INL branch).
  EXPECT_EQ(stress_rate(gudehus_bauer_terms(kPine, Tensor3::Zero(), 1.5), d_compress).norm(), 0.0);
  // Denser than e_d: f_d = 0, not NaN.
  const RateTerms dense = gudehus_bauer_terms(kPine, isotropic(1e3), 0.3);
  EXPECT_EQ(dense.density_factor, 0.0);
  EXPECT_TRUE(stress_rate(dense, d_compress).allFinite());
}

// Inadmissible parameters are refused with a message.
TEST(HypoplasticRate, RejectsInadmissibleParameters) {
  auto p = loblolly_pine_table1();
  p.e_c0 = 0.4;  // below e_d0
  EXPECT_THROW(make_hypoplastic_model(p), std::invalid_argument);
  p = loblolly_pine_table1();
  p.n = 0.0;
  EXPECT_THROW(make_hypoplastic_model(p), std::invalid_argument);
}

}  // namespace
}  // namespace feedflow
