#include "models/material/bulk_compressibility.hpp"

#include <cmath>
#include <stdexcept>

#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

LimitVoidRatios limit_void_ratios(const HypoplasticParameters& hp, double mean_pressure) {
  if (!(mean_pressure >= 0.0))
    throw std::invalid_argument("limit_void_ratios: mean pressure must be >= 0");
  const double factor = std::exp(-std::pow(3.0 * mean_pressure / hp.h_s, hp.n));
  return {hp.e_d0 * factor, hp.e_c0 * factor, hp.e_i0 * factor};
}

BulkCompressibility::BulkCompressibility(const HypoplasticParameters& hp, double reference_density,
                                         double reference_void_ratio)
    : hp_(hp), solid_density_(reference_density * (1.0 + reference_void_ratio)) {
  if (!(reference_density > 0.0) || !(reference_void_ratio > 0.0))
    throw std::invalid_argument("BulkCompressibility: reference density and void ratio must be > 0");
}

std::optional<BulkCompressibility> BulkCompressibility::of(const Material& m) {
  if (!m.hypoplastic) return std::nullopt;
  const auto& hp = *m.hypoplastic;
  const bool design_given = m.overridden.count("bulk.density") > 0;
  const bool loose_given = m.overridden.count("bulk.loose_density") > 0;
  const auto design_anchor = [&] {
    BulkCompressibility b(hp, m.bulk.density, hp.e_d0);
    b.anchor_ = "design density " + format_quantity(m.bulk.density, "kg/m^3") + " at e_d0 = " + format_number(hp.e_d0, 3) +
                (design_given ? " (given by the case)" : "");
    return b;
  };
  if (!m.bulk.loose_density) return design_anchor();
  BulkCompressibility loose(hp, *m.bulk.loose_density, hp.e_i0);
  loose.anchor_ = "loose density " + format_quantity(*m.bulk.loose_density, "kg/m^3") + " at e_i0 = " +
                  format_number(hp.e_i0, 3);
  if (design_given && !loose_given) return design_anchor();
  if (design_given && loose_given) {
    const BulkCompressibility design = design_anchor();
    const double gap = std::abs(design.solid_density() / loose.solid_density() - 1.0);
    if (gap > 0.05)
      throw InputError(m.sources.count("bulk.density") ? m.sources.at("bulk.density") : m.origin, "material.bulk.density",
                       "the design density " + format_quantity(m.bulk.density, "kg/m^3") + " (densest, e_d0 = " +
                           format_number(hp.e_d0, 3) + ") and the loose density " +
                           format_quantity(*m.bulk.loose_density, "kg/m^3") + " (loosest, e_i0 = " +
                           format_number(hp.e_i0, 3) + ") imply solid densities " +
                           format_quantity(design.solid_density(), "kg/m^3") + " and " +
                           format_quantity(loose.solid_density(), "kg/m^3") +
                           ", more than 5 % apart: give one of them, or both consistent");
  }
  return loose;
}

double BulkCompressibility::critical_density(double p) const {
  return solid_density_ / (1.0 + limit_void_ratios(hp_, p).e_c);
}
double BulkCompressibility::loosest_density(double p) const {
  return solid_density_ / (1.0 + limit_void_ratios(hp_, p).e_i);
}
double BulkCompressibility::densest_density(double p) const {
  return solid_density_ / (1.0 + limit_void_ratios(hp_, p).e_d);
}

}  // namespace feedflow
