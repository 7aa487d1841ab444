#include "models/material/dem_parameters.hpp"

namespace feedflow {

std::span<const FieldSpec<DemParticle>> dem_particle_fields() {
  using P = DemParticle;
  static const FieldSpec<P> fields[] = {
      number_field<P>("radius", &P::radius, dim::length, "mm", Range::closed(1e-5, 0.05),
                      "radius of the coarse-grained sphere"),
      number_field<P>("density", &P::density, dim::density, "kg/m^3", Range::closed(1.0, 20000.0),
                      "particle density (set so the packing matches the bulk density)"),
  };
  return fields;
}

std::span<const FieldSpec<DemContactParameters>> dem_contact_fields() {
  using C = DemContactParameters;
  static const FieldSpec<C> fields[] = {
      number_field<C>("alpha_prime", &C::alpha_prime, dim::dimensionless, "-",
                      Range::positive(), "hysteretic loading force scaling coefficient"),
      number_field<C>("chi", &C::chi, dim::dimensionless, "-", Range::closed(1.0, 3.0),
                      "hysteretic loading power index"),
      number_field<C>("A1", &C::a1, dim::force / dim::volume, "N/m^3", Range::non_negative(),
                      "loading stiffness coefficient (growth with maximum overlap)"),
      number_field<C>("A2", &C::a2, dim::force / dim::area, "N/m^2", Range::positive(),
                      "initial loading stiffness coefficient"),
      number_field<C>("A3", &C::a3, dim::dimensionless, "-", Range::positive(),
                      "unloading stiffness coefficient (ratio to loading stiffness)"),
      number_field<C>("K_nc", &C::k_nc, dim::dimensionless, "-", Range::non_negative(),
                      "cohesion force coefficient"),
      number_field<C>("C", &C::c, dim::area, "m^2", Range::positive(),
                      "unloading force scaling coefficient"),
      number_field<C>("youngs_modulus", &C::youngs_modulus, dim::pressure, "MPa",
                      Range{0.0, 1e12, false, true}, "Young's modulus"),
      number_field<C>("poisson_ratio", &C::poisson_ratio, dim::dimensionless, "-",
                      Range{-1.0, 0.5, false, false}, "Poisson's ratio"),
      number_field<C>("restitution", &C::restitution, dim::dimensionless, "-",
                      Range{0.0, 1.0, false, true}, "coefficient of restitution"),
      number_field<C>("friction", &C::friction, dim::dimensionless, "-", Range::non_negative(),
                      "sliding friction coefficient"),
      number_field<C>("rolling_friction", &C::rolling_friction, dim::dimensionless, "-",
                      Range::non_negative(), "rolling friction coefficient"),
  };
  return fields;
}

}  // namespace feedflow
