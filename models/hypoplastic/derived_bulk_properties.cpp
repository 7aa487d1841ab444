#include "models/hypoplastic/derived_bulk_properties.hpp"

#include <cmath>
#include <stdexcept>

namespace feedflow {

DerivedBulkProperties derived_bulk_properties(const HypoplasticParameters& hp,
                                              const BulkCompressibility& compressibility,
                                              double mean_pressure) {
  DerivedBulkProperties d;
  d.mean_pressure = mean_pressure;
  d.void_ratios = limit_void_ratios(hp, mean_pressure);  // checks p >= 0
  const double s = std::sin(hp.phi_c);
  d.critical_friction_angle = hp.phi_c;
  d.critical_ratio_compression = 6.0 * s / (3.0 - s);
  d.critical_ratio_extension = 6.0 * s / (3.0 + s);
  d.critical_density = compressibility.critical_density(mean_pressure);
  d.loosest_density = compressibility.loosest_density(mean_pressure);
  d.densest_density = compressibility.densest_density(mean_pressure);
  return d;
}

DerivedBulkProperties derived_bulk_properties(const Material& material, double mean_pressure) {
  const auto compressibility = BulkCompressibility::of(material);
  if (!compressibility)
    throw std::invalid_argument("derived_bulk_properties: material '" + material.name +
                                "' has no hypoplastic parameters");
  return derived_bulk_properties(*material.hypoplastic, *compressibility, mean_pressure);
}

}  // namespace feedflow
