#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "models/core/errors.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

// Two spheres stacked on a floor under gravity g, each contact at its static Hertz overlap
// (the floor carries both), run with the time step `dt` (0: the stable step) for 2000 steps.
// Returns the engine's spring warning; throws what the run throws.
std::string stack_under(double g, double dt) {
  DemSettings s = hertz_settings(0.5, 0.5, 0.0);
  s.gravity = Vec3(0.0, 0.0, -g);
  s.requested_time_step = dt;
  s.force_time_step = dt > 0.0;
  const double m = kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  const double estar = effective_youngs_modulus(1e6, 0.3);
  // F = (4/3) E* sqrt(R*) delta^1.5 with R* = R/2 between the spheres, R at the floor.
  const double between = std::pow(m * g / (4.0 / 3.0 * estar * std::sqrt(kRadius / 2)), 2.0 / 3.0);
  const double floor = std::pow(2 * m * g / (4.0 / 3.0 * estar * std::sqrt(kRadius)), 2.0 / 3.0);
  ParticleStore p;
  const double z0 = kRadius - floor;
  p.add(Vec3(0.01, 0.01, z0), kRadius, kDensity);
  p.add(Vec3(0.01, 0.01, z0 + 2 * kRadius - between), kRadius, kDensity);
  SimulationBox box{Vec3::Zero(), Vec3(0.02, 0.02, 0.02), {false, false, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  std::ostringstream plan;
  e.prepare(plan);
  e.run_steps(2000);
  std::printf("stack at %g m/s^2, dt %.4g s: contact %.3g R, floor %.3g R\n", g, e.time_step(), (2 * kRadius - (e.particles().position[1] - e.particles().position[0]).norm()) / kRadius, (kRadius - e.particles().position[0].z()) / kRadius);
  return e.spring_warning();
}

// The stiffest design spring's period (the P-W Hertz spring at 0.1 R) for the soft material.
double design_period() {
  const DemSettings s = hertz_settings(0.5, 0.5, 0.0);
  return design_springs(s.material, s.law, s.law, s.time_step.design_overlap).period();
}

// Issue 5: the step comes from the stiffest CURRENT spring. Two spheres stacked under
// 15 000 m/s^2 press their contact to 0.17 R, stiffer than the design contact (0.1 R): at the
// stable step this is warned about, at a forced step beyond period / pi of the contact the run
// stops naming the spring and a safe step; at normal gravity, or at a step with margin (half
// the design step), nothing is said.
TEST(DemLiveTimeStep, OverloadedContactWarnsAtTheDesignStepAndStopsATooLargeStep) {
  const double period = design_period();
  EXPECT_EQ(stack_under(9.81, 0.0), "");                 // 0.002 R: within the design springs
  EXPECT_EQ(stack_under(15000.0, period / 40.0), "");     // deeper, but twice the margin
  const std::string warning = stack_under(15000.0, period / 20.0);  // the design step itself
  EXPECT_NE(warning.find("are stiffer than the time step allows"), std::string::npos) << warning;
  EXPECT_NE(warning.find("P-P tangential spring"), std::string::npos) << warning;
  try {
    stack_under(15000.0, 0.4 * period);  // omega dt = 2.5 at the design contact already
    FAIL() << "a step beyond the stability limit of the current spring was not caught";
  } catch (const NumericalFailure& f) {
    const std::string m = f.what();
    EXPECT_NE(m.find("stability limit"), std::string::npos) << m;
    EXPECT_NE(m.find("A safe time step is"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace feedflow
