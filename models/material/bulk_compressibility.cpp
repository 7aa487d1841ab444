#include "models/material/bulk_compressibility.hpp"

#include <cmath>
#include <stdexcept>

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
  if (m.bulk.loose_density) return BulkCompressibility(hp, *m.bulk.loose_density, hp.e_i0);
  return BulkCompressibility(hp, m.bulk.density, hp.e_d0);
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
