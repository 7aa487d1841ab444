// Janssen bin stresses and the hopper slice stresses (reduced_models.md section 5, T1).
#include <gtest/gtest.h>

#include <cmath>

#include "models/hopper/bin_stresses.hpp"
#include "models/hopper/hopper_slice_stresses.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

// T1 (Tardos): round bin, rho_b 1560, g 10, D 1.8 m, phi 24.1, phi_w 20.2 deg, Rankine K:
// sigma_v,max = 45.9 kPa with K mu rounded to 0.153 (45.4 kPa exact), z_99% = 13.55 m and the
// wall normal stress 19.1 kPa.
TEST(HopperBinStresses, T1JanssenRoundBin) {
  const double k = janssen_stress_ratio(StressRatioRule::rankine_active, 24.1 * kDegree);
  const double mu = std::tan(20.2 * kDegree);
  EXPECT_NEAR(k * mu, 0.1546, 0.0001);
  const JanssenBin exact{round_bin_hydraulic_radius(1.8), 1560, k, mu, 0.0, 10.0};
  EXPECT_NEAR(janssen_asymptotic_stress(exact), 45.4e3, 50);
  const JanssenBin rounded{round_bin_hydraulic_radius(1.8), 1560, 0.153 / mu, mu, 0.0, 10.0};
  EXPECT_NEAR(janssen_asymptotic_stress(rounded), 45.9e3, 50);
  EXPECT_NEAR(janssen_depth_to_fraction(rounded, 0.99), 13.55, 0.01);
  const auto deep = janssen_stress(exact, 100.0);
  EXPECT_NEAR(deep.wall_normal, 19.1e3, 50);
  EXPECT_NEAR(deep.wall_shear, mu * deep.wall_normal, 1e-9);
  // The profile starts at the surcharge and rises monotonically to the asymptote.
  const auto profile = janssen_profile(exact, 20.0, 21);
  EXPECT_EQ(profile.front().vertical, 0.0);
  for (std::size_t i = 1; i < profile.size(); ++i)
    EXPECT_GT(profile[i].vertical, profile[i - 1].vertical);
  EXPECT_LT(profile.back().vertical, janssen_asymptotic_stress(exact));
}

// The stress-ratio options of section 5 and the plane-bin hydraulic radius.
TEST(HopperBinStresses, StressRatioRulesAndHydraulicRadius) {
  const double s = std::sin(40 * kDegree);
  EXPECT_DOUBLE_EQ(janssen_stress_ratio(StressRatioRule::jaky, 40 * kDegree), 1 - s);
  EXPECT_DOUBLE_EQ(janssen_stress_ratio(StressRatioRule::en1991_4, 40 * kDegree), 1.1 * (1 - s));
  EXPECT_DOUBLE_EQ(janssen_stress_ratio(StressRatioRule::schulze, 40 * kDegree), 1.2 * (1 - s));
  EXPECT_DOUBLE_EQ(janssen_stress_ratio(StressRatioRule::rankine_active, 40 * kDegree),
                   (1 - s) / (1 + s));
  EXPECT_DOUBLE_EQ(plane_bin_hydraulic_radius(0.6), 0.3);
  EXPECT_DOUBLE_EQ(plane_bin_hydraulic_radius(0.6, 0.6), 0.15);  // square: D/4
}

// The slice solution satisfies its equation d sigma_v/dh = n sigma_v/h - rho g (central
// differences, also at n = 1), starts at sigma_vt and becomes radial (sigma_v ~ h) near the apex.
TEST(HopperSliceStresses, SolvesTheSliceEquation) {
  const double lambda = passive_hopper_stress_ratio(30 * kDegree, 50 * kDegree, 8.5 * kDegree);
  EXPECT_NEAR(lambda, 1.997, 0.001);
  for (double ratio : {lambda, 0.0}) {
    HopperSlice s{FlowGeometry::plane, 30 * kDegree, 8.5 * kDegree, ratio, 290, 0.55, 800.0};
    if (ratio == 0.0)  // choose lambda_h so that n = 1 exactly
      s.stress_ratio = 2.0 / (1.0 + std::tan(s.wall_friction_angle) / std::tan(s.semi_angle));
    const double n = slice_exponent(s);
    EXPECT_NEAR(slice_stress(s, 0.55).vertical, 800.0, 1e-9);
    for (double h : {0.05, 0.2, 0.4}) {
      const double dh = 1e-6;
      const double slope = (slice_stress(s, h + dh).vertical - slice_stress(s, h - dh).vertical) / (2 * dh);
      EXPECT_NEAR(slope, n * slice_stress(s, h).vertical / h - 290 * 9.81, 1e-3) << "n " << n;
    }
  }
  HopperSlice s{FlowGeometry::plane, 30 * kDegree, 8.5 * kDegree, lambda, 290, 0.55, 800.0};
  const double n = slice_exponent(s);
  EXPECT_NEAR(n, 1.514, 0.001);
  // Radial limit: sigma_v/h -> rho g/(n-1); at h/h_t = 1.8e-6 within (h/h_t)^(n-1) = 0.1 %.
  EXPECT_NEAR(slice_stress(s, 1e-6).vertical / 1e-6 / (290 * 9.81 / (n - 1)), 1.0, 2e-3);
}

// The seed hopper emptying: Janssen down the bin, then the slice; heights fall from the fill
// level to the outlet, the wall stress jumps up at the transition (the switch) and the vertical
// stress falls towards the outlet as the field turns radial (sigma_v ~ h).
TEST(HopperSliceStresses, EmptyingSiloProfile) {
  Hopper h;
  h.shape = "wedge";
  h.semi_angle = 30 * kDegree;
  h.outlet_width = 0.06;
  h.bin_width = 0.62;
  h.fill_height = 0.68 + h.outlet_height();
  h.slot_length = 0.5;
  const auto p =
      emptying_silo_profile(h, 290, 50 * kDegree, 8.5 * kDegree, StressRatioRule::schulze, 20);
  ASSERT_EQ(p.size(), 40u);
  for (std::size_t i = 1; i < p.size(); ++i) EXPECT_LE(p[i].height, p[i - 1].height);
  EXPECT_NEAR(p.front().height, h.fill_height, 1e-12);
  EXPECT_NEAR(p.back().height, h.outlet_height(), 1e-12);
  EXPECT_EQ(p.front().vertical, 0.0);
  EXPECT_NEAR(p[19].vertical, p[20].vertical, 1e-9);  // continuous sigma_v at the transition
  EXPECT_GT(p[20].wall_normal, 2.0 * p[19].wall_normal);  // the switch stress
  EXPECT_LT(p.back().vertical, 0.5 * p[20].vertical);
}

}  // namespace
}  // namespace feedflow
