#pragma once
// DEM parameters of a material (seed Table 2): the coarse-grained particle, and one contact
// parameter set for particle-particle and one for particle-wall contacts. Units follow the
// force laws of models.md section 3 (hysteretic loading force alpha' k1 delta^2, so k1 and A2
// are in N/m^2, A1 in N/m^3, and C in m^2), as used in LIGGGHTS-INL as raw SI numbers.
#include <span>
#include <vector>

#include "models/core/field_spec.hpp"

namespace feedflow {

struct DemParticle {
  double radius = 0.0;   // [m]
  double density = 0.0;  // [kg/m^3], chosen so the packing matches the bulk density
};

struct DemContactParameters {
  double alpha_prime = 0.0;       // loading force scaling [-]
  double chi = 2.0;               // loading power index [-]
  double a1 = 0.0;                // growth of loading stiffness with max overlap [N/m^3]
  double a2 = 0.0;                // initial (virgin) loading stiffness [N/m^2]
  double a3 = 0.0;                // unloading/loading stiffness ratio [-]
  double k_nc = 0.0;              // cohesion stiffness factor [-]
  double c = 0.0;                 // unloading force scaling [m^2]
  double youngs_modulus = 0.0;    // [Pa]
  double poisson_ratio = 0.0;     // [-]
  double restitution = 0.0;       // coefficient of restitution [-]
  double friction = 0.0;          // sliding friction coefficient [-]
  double rolling_friction = 0.0;  // rolling friction coefficient [-]
};

struct DemParameters {
  DemParticle particle;
  DemContactParameters particle_particle;
  DemContactParameters particle_wall;
};

std::span<const FieldSpec<DemParticle>> dem_particle_fields();
std::span<const FieldSpec<DemContactParameters>> dem_contact_fields();

}  // namespace feedflow
