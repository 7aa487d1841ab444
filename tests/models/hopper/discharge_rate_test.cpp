// Hopper discharge rate: Johanson, Beverloo, Brown-Richards, hourglass and Carleton against
// reduced_models.md section 2 (worked examples of item 6, coefficient table of item 3, T7).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "models/hopper/critical_outlet.hpp"
#include "models/hopper/discharge_rate.hpp"
#include "models/hopper/minimum_energy_discharge.hpp"
#include "models/hopper/radial_stress_field.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

// Section 2 item 6, seed hopper (theta 30 deg, B 60 mm, rho_b 290, per metre of slot):
// Johanson cohesionless 12.4 kg/s; with the section 1.4 flow function ff_a = 2.78 and 9.0 kg/s.
TEST(HopperDischarge, JohansonSeedHopper) {
  const auto rho = BulkDensity::constant(290);
  const auto free = johanson_discharge(FlowGeometry::plane, 30 * kDegree, 0.06, 1.315,
                                       FlowFunction::cohesionless(), rho);
  EXPECT_NEAR(free.rate, 12.4, 0.05);
  EXPECT_DOUBLE_EQ(free.cohesion_factor, 1.0);
  EXPECT_TRUE(std::isinf(free.actual_flow_factor));
  // Cohesionless closed form: 0.931 rho_b sqrt(g) B^(3/2) at 30 deg.
  EXPECT_NEAR(free.rate / (290 * std::sqrt(9.81) * std::pow(0.06, 1.5)), 0.931, 0.0005);
  const double ff =
      solve_radial_stress_field(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree)
          ->flow_factor;
  const auto cohesive = johanson_discharge(FlowGeometry::plane, 30 * kDegree, 0.06, ff,
                                           FlowFunction::linear(0.1, 50), rho);
  EXPECT_NEAR(cohesive.actual_flow_factor, 2.78, 0.005);
  EXPECT_NEAR(cohesive.rate, 9.0, 0.05);
  // Per slot: a 0.5 m slot delivers half a metre's worth.
  EXPECT_NEAR(slot_rate(cohesive.rate, 0.5), 0.5 * cohesive.rate, 1e-12);
}

// Johanson's rate goes to zero at the critical outlet width of section 1 (same ff, same FF).
TEST(HopperDischarge, JohansonVanishesAtTheCriticalOutlet) {
  const auto rho = BulkDensity::constant(290);
  const auto f = FlowFunction::linear(0.1, 50);
  const double bc = jenike_critical_outlet(FlowGeometry::plane, 30 * kDegree, 1.315, f, rho).width;
  EXPECT_NEAR(
      johanson_discharge(FlowGeometry::plane, 30 * kDegree, bc * (1 + 1e-9), 1.315, f, rho).rate,
      0.0, 1e-3);
  EXPECT_EQ(johanson_discharge(FlowGeometry::plane, 30 * kDegree, 0.9 * bc, 1.315, f, rho).rate,
            0.0);
  EXPECT_GT(johanson_discharge(FlowGeometry::plane, 30 * kDegree, 1.5 * bc, 1.315, f, rho).rate,
            1.0);
  // The cone: W = rho_b pi B^2/4 sqrt(B g / (4 tan theta)) for a cohesionless solid.
  const auto cone = johanson_discharge(FlowGeometry::conical, 30 * kDegree, 0.1, 1.5,
                                       FlowFunction::cohesionless(), rho);
  EXPECT_NEAR(cone.rate, 290 * std::numbers::pi * 0.01 / 4 *
                             std::sqrt(0.1 * 9.81 / (4 * std::tan(30 * kDegree))), 1e-12);
}

// Beverloo slot with k = 1.5, d = 0.82 mm, C2 = 1.03: 13.3 kg/s per metre (item 6); the
// slot-length form subtracts k d from the length too.
TEST(HopperDischarge, BeverlooSlotAndCircle) {
  EXPECT_NEAR(beverloo_slot_rate_per_metre(290, 0.06, 0.82e-3), 13.3, 0.05);
  EXPECT_NEAR(beverloo_slot_rate(290, 0.06, 0.5, 0.82e-3),
              beverloo_slot_rate_per_metre(290, 0.06, 0.82e-3) * (0.5 - 1.5 * 0.82e-3), 1e-12);
  // Circle: 0.58 rho sqrt(g) (D - k d)^(5/2) with D = 0.1 m, d = 1 mm, k = 1.5.
  EXPECT_NEAR(beverloo_circular_rate(1000, 0.1, 1e-3), 0.58 * 1000 * std::sqrt(9.81) *
                                                           std::pow(0.0985, 2.5), 1e-12);
  EXPECT_THROW(beverloo_slot_rate_per_metre(290, 1e-3, 0.82e-3), std::invalid_argument);
}

// Section 2 item 3: the Brown-Richards coefficient table 1.701/1.222/1.025/0.894/0.859/1.023
// at 10/20/30/45/60/90 deg, with e = 1.492, 1.435 and 1.112 at 10, 30 and 90 deg.
TEST(HopperDischarge, BrownRichardsCoefficientTable) {
  struct Row { double theta, coefficient, e; };
  for (const auto& r : {Row{10, 1.701, 1.492}, Row{20, 1.222, 0}, Row{30, 1.025, 1.435},
                        Row{45, 0.894, 0}, Row{60, 0.859, 0}, Row{90, 1.023, 1.112}}) {
    const auto b = brown_richards_wedge(r.theta * kDegree);
    EXPECT_NEAR(b.coefficient, r.coefficient, 0.0005) << "theta " << r.theta;
    if (r.e > 0) {
      EXPECT_NEAR(b.energy_constant, r.e, 0.0005) << "theta " << r.theta;
    }
  }
  // Small angles tend to theta / (sqrt 2 sin^(3/2) theta).
  const double t = 2 * kDegree;
  EXPECT_NEAR(brown_richards_wedge(t).coefficient / (t / (std::sqrt(2.0) * std::pow(std::sin(t), 1.5))),
              1.0, 0.01);
}

// Rose & Tanaka (1956, The Engineer 202) as Nedderman (1992, Statics and Kinematics of Granular
// Materials, ch. 10) and reduced_models.md section 2 item 1 give it: F = (tan theta tan phi_d)^-0.35
// below theta = 90 deg - phi_d, else 1. 1.212 at theta = 30 deg, phi_d = 45 deg is that published
// form evaluated by hand (0.57735^-0.35); no tabulated value of the paper was at hand to cite.
TEST(HopperDischarge, RoseTanakaHopperFactor) {
  EXPECT_NEAR(rose_tanaka_factor(30 * kDegree, 45 * kDegree), 1.212, 0.0005);
  EXPECT_DOUBLE_EQ(rose_tanaka_factor(45 * kDegree, 45 * kDegree), 1.0);  // continuous at the stagnant zone
  EXPECT_DOUBLE_EQ(rose_tanaka_factor(60 * kDegree, 45 * kDegree), 1.0);  // flatter: a flat bottom
  EXPECT_GT(rose_tanaka_factor(15 * kDegree, 45 * kDegree), rose_tanaka_factor(30 * kDegree, 45 * kDegree));  // steeper, faster
  EXPECT_THROW(rose_tanaka_factor(0.0, 45 * kDegree), std::invalid_argument);
}

// T7: the flat-bottomed slot by Brown's theory, 1.023, against Beverloo's empirical C2 = 1.03;
// and the seed hopper by Brown, 13.7 kg/s per metre (item 6).
TEST(HopperDischarge, T7FlatSlotAndSeedHopper) {
  EXPECT_NEAR(brown_richards_wedge(90 * kDegree).coefficient, 1.03, 0.01);
  EXPECT_NEAR(brown_richards_rate_per_metre(290, 0.06, 30 * kDegree), 13.7, 0.05);
}

// Hourglass: coefficient theta/(sqrt2 sin^(3/2) theta) sqrt((k+1)/(k-2)) = 1.54 at theta 30,
// phi 40 deg, above every other model (an upper bound); a finite top lowers it; the plane
// form refuses phi < 19.5 deg.
TEST(HopperDischarge, HourglassUpperBound) {
  const double scale = 290 * std::sqrt(9.81) * std::pow(0.06, 1.5);
  const double w = hourglass_rate(FlowGeometry::plane, 290, 0.06, 30 * kDegree, 40 * kDegree);
  EXPECT_NEAR(w / scale, 1.54, 0.005);
  EXPECT_GT(w, brown_richards_rate_per_metre(290, 0.06, 30 * kDegree));
  EXPECT_GT(w, beverloo_slot_rate_per_metre(290, 0.06, 0.82e-3));
  EXPECT_LT(hourglass_rate(FlowGeometry::plane, 290, 0.06, 30 * kDegree, 40 * kDegree, 0.2), w);
  // Cone, tall: V^2 = g r0 (k+1)/(2k-3).
  const double k = (1 + std::sin(40 * kDegree)) / (1 - std::sin(40 * kDegree));
  const double r0 = 0.05 / std::sin(30 * kDegree);
  EXPECT_NEAR(hourglass_rate(FlowGeometry::conical, 290, 0.1, 30 * kDegree, 40 * kDegree),
              290 * 2 * std::numbers::pi * r0 * r0 * (1 - std::cos(30 * kDegree)) *
                  std::sqrt(9.81 * r0 * (k + 1) / (2 * k - 3)),
              1e-9);
  EXPECT_THROW(hourglass_rate(FlowGeometry::plane, 290, 0.06, 30 * kDegree, 15 * kDegree),
               std::invalid_argument);
}

// Carleton's air drag on the seed hopper (B 60 mm, theta 30 deg, plane), section 2 item 5:
// V0 falls by about 11 % (d 0.82 mm) and 32 % (d 0.38 mm) at rho_p 433 kg/m^3, by 8 % / 25 %
// at 600 and 5 % / 17 % at 1000 kg/m^3; without air the drag factor is 1.
TEST(HopperDischarge, CarletonAirDragOnLightBiomass) {
  struct Row { double rho_p, d, drop; };
  for (const auto& r : {Row{433, 0.82e-3, 0.11}, Row{433, 0.38e-3, 0.32}, Row{600, 0.82e-3, 0.08},
                        Row{600, 0.38e-3, 0.25}, Row{1000, 0.82e-3, 0.05},
                        Row{1000, 0.38e-3, 0.17}})
    EXPECT_NEAR(1 - air_drag_factor(FlowGeometry::plane, 30 * kDegree, 0.06, {r.rho_p, r.d}),
                r.drop, 0.006)
        << "rho_p " << r.rho_p << " d " << r.d;
  AirDrag vacuum{433, 0.38e-3, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(air_drag_factor(FlowGeometry::plane, 30 * kDegree, 0.06, vacuum), 1.0);
  // Conical: 4 V0^2 sin theta / B = g without drag.
  EXPECT_NEAR(carleton_outlet_velocity(FlowGeometry::conical, 30 * kDegree, 0.1, vacuum),
              std::sqrt(9.81 * 0.1 / (4 * 0.5)), 1e-12);
  // The drag term balances: plug V0 back into the plane equation.
  const AirDrag pine{433, 0.82e-3};
  const double v = carleton_outlet_velocity(FlowGeometry::plane, 30 * kDegree, 0.06, pine);
  const double drag = 15 * std::cbrt(1.2) * std::pow(1.8e-5, 2.0 / 3) * std::pow(v, 4.0 / 3) /
                      (433 * std::pow(0.82e-3, 5.0 / 3));
  EXPECT_NEAR(2 * v * v * 0.5 / 0.06 + drag, 9.81, 1e-9);
}

}  // namespace
}  // namespace feedflow
