#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

// Kinetic plus Hertz elastic energy, (8/15) E* sqrt(R*) delta^(5/2) per pair and per wall
// contact (E* of the P-W set equals the P-P one here).
double total_energy(const DemEngine& e) {
  const ParticleStore& p = e.particles();
  const double estar = effective_youngs_modulus(1e6, 0.3);
  double energy = p.kinetic_energy();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double d = p.radius[i] + p.radius[j] - (p.position[i] - p.position[j]).norm();
      const double rstar = p.radius[i] * p.radius[j] / (p.radius[i] + p.radius[j]);
      if (d > 0) energy += 8.0 / 15.0 * estar * std::sqrt(rstar) * std::pow(d, 2.5);
    }
    for (const Wall& w : e.walls()) {
      const double d = p.radius[i] - w.touch(p.position[i]).gap;
      if (d > 0) energy += 8.0 / 15.0 * estar * std::sqrt(p.radius[i]) * std::pow(d, 2.5);
    }
  }
  return energy;
}

// An elastic (e = 1), frictionless gas of 125 spheres in a walled box keeps its energy
// (kinetic + elastic) to a small drift at a fine step; the plan says the tangential and
// rolling kernels are skipped.
TEST(DemEngine, ElasticGasConservesEnergy) {
  DemSettings s = hertz_settings(1.0, 0.0, 0.0);
  s.gravity = Vec3::Zero();
  ParticleStore p;
  add_lattice(p, Vec3(0.004, 0.004, 0.004), 5, 5, 5, 0.0035, 0.5);
  SimulationBox box{Vec3::Zero(), Vec3(0.022, 0.022, 0.022), {false, false, false}};
  DemEngine e(s, box, p);
  add_box_walls(e, box.lower, box.upper);
  std::ostringstream plan;
  e.prepare(plan);
  EXPECT_NE(plan.str().find("rolling kernel skipped: mu_r = 0"), std::string::npos) << plan.str();
  EXPECT_NE(plan.str().find("tangential kernel skipped: mu = 0"), std::string::npos);
  EXPECT_TRUE(e.effective_law().rolling.is<NoRolling>());
  const double e0 = total_energy(e);
  s.requested_time_step = e.time_step() / 4.0;
  DemEngine fine(s, box, p);
  add_box_walls(fine, box.lower, box.upper);
  std::ostringstream quiet;
  fine.prepare(quiet);
  fine.advance_to(0.02);
  const double drift = std::abs(total_energy(fine) - e0) / e0;
  std::printf("elastic gas: %ld steps of %.3g s, relative energy drift %.3g, %zu rebuilds\n",
              fine.step(), fine.time_step(), drift, fine.neighbours().rebuild_count());
  EXPECT_LT(drift, 1e-4);
  EXPECT_GT(fine.neighbours().rebuild_count(), 3u);  // the gas moved and collided
}

// A sphere dropped on a plane comes to rest with the Hertz overlap of its weight:
// m g = (4/3) E* sqrt(R delta) delta with the P-W parameters.
TEST(DemEngine, SphereDroppedOnPlaneSettlesAtTheHertzOverlap) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  ParticleStore p;
  p.add(Vec3(0.01, 0.01, 0.005), kRadius, kDensity);
  SimulationBox box{Vec3::Zero(), Vec3(0.02, 0.02, 0.02), {false, false, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  std::ostringstream plan;
  e.prepare(plan);
  e.advance_to(0.3);
  const double m = e.particles().mass[0];
  const double estar = effective_youngs_modulus(1e6, 0.3);
  // Solve m g = (4/3) E* sqrt(R) delta^1.5.
  const double delta = std::pow(m * 9.81 / (4.0 / 3.0 * estar * std::sqrt(kRadius)), 2.0 / 3.0);
  const double overlap = kRadius - e.particles().position[0].z();
  std::printf("drop: overlap %.6g m, Hertz %.6g m, speed %.3g m/s\n", overlap, delta,
              e.max_speed());
  EXPECT_NEAR(overlap, delta, 1e-4 * delta);
  EXPECT_LT(e.max_speed(), 1e-6);
}

// A sphere inside a drum turning at Omega about its axis is carried into rolling: its contact
// point moves with the drum wall (no slip) and it spins in the drum's sense at about
// w r = Omega R_drum (off by the centre's pendulum motion).
TEST(DemEngine, SphereRollsInsideARotatingCylinder) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  const double drum = 0.02, omega = 3.0;
  ParticleStore p;
  p.add(Vec3(0.0, 0.0, -drum + kRadius + 1e-4), kRadius, kDensity);
  SimulationBox box{Vec3(-0.025, -0.01, -0.025), Vec3(0.025, 0.01, 0.025), {false, false, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::cylinder("drum", Vec3::Zero(), Vec3::UnitY(), drum, true)
                 .moving(Vec3::Zero(), omega * Vec3::UnitY()));
  std::ostringstream plan;
  e.prepare(plan);
  EXPECT_NE(plan.str().find("allows for moving walls up to 0.0552 m/s"), std::string::npos)
      << plan.str();  // Omega (R_drum - R - 0.1 mm): the sphere's distance from the axis
  e.advance_to(0.3);
  const ParticleStore& q = e.particles();
  const Vec3 x = q.position[0];
  const Vec3 radial = Vec3(x.x(), 0.0, x.z());
  const Vec3 n = -radial.normalized();  // from the wall towards the centre
  const double lever = drum - radial.norm();  // centre to the contact point
  const Vec3 contact_velocity = q.velocity[0] + q.angular_velocity[0].cross(-lever * n);
  const Vec3 wall_velocity = omega * Vec3::UnitY().cross(x - lever * n);
  const double slip = (contact_velocity - wall_velocity).norm();
  const double ratio = q.angular_velocity[0].y() * lever / (omega * drum);
  std::printf("drum: spin %.4g rad/s, w r / (Omega R) = %.4f, slip %.3g m/s, centre speed %.3g m/s\n",
              q.angular_velocity[0].y(), ratio, slip, q.velocity[0].norm());
  EXPECT_LT(slip, 1e-3 * omega * drum);
  EXPECT_GT(ratio, 0.5);  // same sense as the drum
  EXPECT_LT(std::abs(ratio - 1.0), 1.2 * q.velocity[0].norm() / (omega * drum) + 1e-3);
}

// A pour of 216 spheres into a box comes to rest: after 0.5 s the fastest moves < 5 mm/s and
// every sphere lies inside the box.
TEST(DemEngine, PouredPackingComesToRest) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.1);
  ParticleStore p;
  add_lattice(p, Vec3(0.003, 0.003, 0.003), 6, 6, 6, 0.0036, 0.05);
  SimulationBox box{Vec3::Zero(), Vec3(0.03, 0.03, 0.03), {false, false, false}};
  DemEngine e(s, box, p);
  add_box_walls(e, box.lower, box.upper);
  std::ostringstream plan;
  e.prepare(plan);
  e.advance_to(0.5);
  std::printf("pour: %zu spheres, max speed %.3g m/s after %ld steps\n%s", e.particles().size(),
              e.max_speed(), e.step(), e.performance_report().c_str());
  EXPECT_LT(e.max_speed(), 5e-3);
  for (const auto& x : e.particles().position) {
    EXPECT_TRUE((x.array() > 0.0).all() && (x.array() < 0.03).all());
  }
}

}  // namespace
}  // namespace feedflow
