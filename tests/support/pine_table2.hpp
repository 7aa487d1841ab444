#pragma once
// Seed Table 2 (milled loblolly pine, DEM) for tests and benchmarks that do not read the
// material file: the same values as cases/materials/loblolly_pine.toml.
#include "models/material/dem_parameters.hpp"

namespace feedflow::testing {

inline DemContactParameters pine_table2_contact(double friction, double rolling_friction) {
  DemContactParameters p;
  p.alpha_prime = 20;
  p.chi = 2;
  p.a1 = 6e8;
  p.a2 = 5e4;
  p.a3 = 5;
  p.k_nc = 1e-4;
  p.c = 1e-7;
  p.youngs_modulus = 1e6;
  p.poisson_ratio = 0.3;
  p.restitution = 0.3;
  p.friction = friction;
  p.rolling_friction = rolling_friction;
  return p;
}

// The particle-particle and particle-wall columns.
inline DemContactParameters pine_table2_particle_particle() { return pine_table2_contact(0.5, 0.8); }
inline DemContactParameters pine_table2_particle_wall() { return pine_table2_contact(0.2, 0.6); }

// Spheres of `radius` [m] and Table 2's density with both columns.
inline DemParameters pine_table2(double radius) {
  DemParameters dem;
  dem.particle = {radius, 390.0};
  dem.particle_particle = pine_table2_particle_particle();
  dem.particle_wall = pine_table2_particle_wall();
  return dem;
}

}  // namespace feedflow::testing
