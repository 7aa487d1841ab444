#include "models/material/material.hpp"

#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {
// Bulk and particle densities from aerated powders to metal ores [kg/m^3].
constexpr Range kDensityRange{1.0, 20000.0, true, true};
// Grain sizes from fine powders to lump [m].
constexpr Range kSizeRange{1e-6, 0.5, true, true};
}  // namespace

std::span<const FieldSpec<BulkProperties>> bulk_fields() {
  using B = BulkProperties;
  static const FieldSpec<B> fields[] = {
      number_field<B>("density", &B::density, dim::density, "kg/m^3", kDensityRange,
                      "design bulk density"),
      optional_number_field<B>("loose_density", &B::loose_density, dim::density, "kg/m^3",
                               kDensityRange, "loose (poured) bulk density, at most the design density"),
      number_field<B>("wall_friction_angle", &B::wall_friction_angle, dim::angle, "deg",
                      Range::half_open(0.0, 90.0 * kDegree),
                      "wall friction angle on the reference wall"),
      optional_number_field<B>("moisture_content", &B::moisture_content, dim::dimensionless,
                               "%", Range::half_open(0.0, 1.0), "moisture content (wet basis)"),
  };
  return fields;
}

std::span<const FieldSpec<ParticleSizeDistribution>> psd_fields() {
  using P = ParticleSizeDistribution;
  static const FieldSpec<P> fields[] = {
      number_field<P>("d10", &P::d10, dim::length, "mm", kSizeRange,
                      "particle size at 10 % cumulative passing"),
      number_field<P>("d50", &P::d50, dim::length, "mm", kSizeRange,
                      "median particle size (50 % passing)"),
      number_field<P>("d90", &P::d90, dim::length, "mm", kSizeRange,
                      "particle size at 90 % cumulative passing"),
  };
  return fields;
}

std::vector<FieldProblem> check(const BulkProperties& b) {
  if (!b.loose_density || *b.loose_density <= b.density) return {};
  return {{"loose_density", "must not exceed the design density (" + format_quantity(b.density, "kg/m^3") +
                                "), got " + format_quantity(*b.loose_density, "kg/m^3")}};
}

std::vector<FieldProblem> check(const ParticleSizeDistribution& p) {
  std::vector<FieldProblem> problems;
  if (!(p.d10 <= p.d50))
    problems.push_back({"d50", "must be at least d10 (" + format_quantity(p.d10, "mm") + ")"});
  if (!(p.d50 <= p.d90))
    problems.push_back({"d90", "must be at least d50 (" + format_quantity(p.d50, "mm") + ")"});
  return problems;
}

}  // namespace feedflow
