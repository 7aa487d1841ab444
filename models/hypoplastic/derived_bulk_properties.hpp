#pragma once
// What the reduced models need from the hypoplastic parameters, in one call: the critical-state
// friction angle with the critical stress ratios in triaxial compression and extension, and the
// compressibility (limiting void ratios and bulk densities) at a mean pressure
// (models.md 1.4; bulk_compressibility.hpp for the Bauer compression law).
#include "models/material/bulk_compressibility.hpp"
#include "models/material/material.hpp"

namespace feedflow {

struct DerivedBulkProperties {
  double mean_pressure = 0.0;            // p [Pa]
  double critical_friction_angle = 0.0;  // phi_c [rad]
  double critical_ratio_compression = 0.0;  // M_c = 6 sin phi_c / (3 - sin phi_c) [-]
  double critical_ratio_extension = 0.0;    // M_e = 6 sin phi_c / (3 + sin phi_c) [-]
  LimitVoidRatios void_ratios{};            // e_d, e_c, e_i at p [-]
  double critical_density = 0.0;            // rho_b on the critical-state line at p [kg/m^3]
  double loosest_density = 0.0;             // at e_i(p) [kg/m^3]
  double densest_density = 0.0;             // at e_d(p) [kg/m^3]
};

DerivedBulkProperties derived_bulk_properties(const HypoplasticParameters& hp,
                                              const BulkCompressibility& compressibility,
                                              double mean_pressure);

// For a material with a hypoplastic section; throws std::invalid_argument naming the material
// when it has none.
DerivedBulkProperties derived_bulk_properties(const Material& material, double mean_pressure);

}  // namespace feedflow
