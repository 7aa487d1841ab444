#pragma once
// Test support: a soft pine-like material (seed Table 2 particle, E = 1 MPa) with the Hertz
// law, quiet settings, and a lattice of spheres.
#include <random>

#include "fullsim/dem/dem_engine.hpp"
#include "tests/support/pine_table2.hpp"

namespace feedflow::dem_test {

inline DemContactParameters soft_contact(double restitution, double friction,
                                         double rolling_friction) {
  DemContactParameters p;
  p.youngs_modulus = 1e6;
  p.poisson_ratio = 0.3;
  p.restitution = restitution;
  p.friction = friction;
  p.rolling_friction = rolling_friction;
  p.alpha_prime = 20;
  p.chi = 2;
  p.a1 = 6e8;
  p.a2 = 5e4;
  p.a3 = 5;
  p.k_nc = 1e-4;
  p.c = 1e-7;
  return p;
}

constexpr double kRadius = 1.5e-3;   // [m]
constexpr double kDensity = 390.0;   // [kg/m^3]

// Hertz + Mindlin, no rolling unless mu_r > 0, no cohesion.
inline DemSettings hertz_settings(double restitution, double friction, double rolling_friction) {
  DemSettings s;
  s.material.particle = {kRadius, kDensity};
  s.material.particle_particle = soft_contact(restitution, friction, rolling_friction);
  s.material.particle_wall = soft_contact(restitution, friction, rolling_friction);
  s.law = choose_contact_law("hertz", "mindlin", "cdt", "none");
  return s;
}

// Table 2's particle-particle and particle-wall sets with Hertz + Mindlin + CDT rolling, spheres
// of 3 mm and 390 kg/m^3: the coarse twins of the scene tests.
inline DemSettings pine_twin_settings() {
  DemSettings s;
  s.material.particle = {3e-3, kDensity};
  s.material.particle_particle = testing::pine_table2_particle_particle();
  s.material.particle_wall = testing::pine_table2_particle_wall();
  s.law = choose_contact_law("hertz", "mindlin", "cdt", "none");
  return s;
}

// nx x ny x nz spheres on a cubic lattice of `spacing` from `origin`, random velocities of up to
// `speed` (fixed seed).
inline void add_lattice(ParticleStore& p, const Vec3& origin, int nx, int ny, int nz,
                        double spacing, double speed, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 x = origin + spacing * Vec3(i, j, k);
        p.add(x, kRadius, kDensity, k, speed * Vec3(u(rng), u(rng), u(rng)));
      }
}

// The four side walls of the box [lower, upper] facing inwards (x-, x+, y-, y+).
inline void add_side_walls(DemEngine& e, const Vec3& lower, const Vec3& upper) {
  e.add_wall(Wall::plane("x-", lower, Vec3::UnitX()));
  e.add_wall(Wall::plane("x+", upper, -Vec3::UnitX()));
  e.add_wall(Wall::plane("y-", lower, Vec3::UnitY()));
  e.add_wall(Wall::plane("y+", upper, -Vec3::UnitY()));
}

// The six walls of the box [lower, upper] facing inwards.
inline void add_box_walls(DemEngine& e, const Vec3& lower, const Vec3& upper) {
  add_side_walls(e, lower, upper);
  e.add_wall(Wall::plane("z-", lower, Vec3::UnitZ()));
  e.add_wall(Wall::plane("z+", upper, -Vec3::UnitZ()));
}

}  // namespace feedflow::dem_test
