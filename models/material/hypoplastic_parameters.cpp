#include "models/material/hypoplastic_parameters.hpp"

#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {
// Void ratios at zero pressure: sands 0.5-1.2, fluffy biomass a few.
constexpr Range kVoidRatioRange{0.0, 10.0, false, true};
}  // namespace

std::span<const FieldSpec<HypoplasticParameters>> hypoplastic_fields() {
  using P = HypoplasticParameters;
  static const FieldSpec<P> fields[] = {
      number_field<P>("phi_c", &P::phi_c, dim::angle, "deg", Range::open(0.0, 90.0 * kDegree),
                      "critical-state friction angle"),
      number_field<P>("h_s", &P::h_s, dim::pressure, "kPa", Range{0.0, 1e12, false, true},
                      "granulate hardness (pressure scale of the compression law)"),
      number_field<P>("n", &P::n, dim::dimensionless, "-", Range{0.0, 1.0, false, true},
                      "exponent of the compression law"),
      number_field<P>("e_d0", &P::e_d0, dim::dimensionless, "-", kVoidRatioRange,
                      "minimum void ratio at zero pressure"),
      number_field<P>("e_c0", &P::e_c0, dim::dimensionless, "-", kVoidRatioRange,
                      "critical void ratio at zero pressure"),
      number_field<P>("e_i0", &P::e_i0, dim::dimensionless, "-", kVoidRatioRange,
                      "maximum void ratio at zero pressure"),
      number_field<P>("alpha", &P::alpha, dim::dimensionless, "-", Range::non_negative(),
                      "exponent of the density factor (peak friction, dilatancy)"),
      number_field<P>("beta", &P::beta, dim::dimensionless, "-", Range::non_negative(),
                      "exponent of the stiffness increase with density"),
  };
  return fields;
}

std::vector<FieldProblem> check(const HypoplasticParameters& p) {
  std::vector<FieldProblem> problems;
  if (!(p.e_d0 < p.e_c0))
    problems.push_back({"e_c0", "must exceed e_d0 (" + format_number(p.e_d0) + "), got " +
                                    format_number(p.e_c0)});
  if (!(p.e_c0 < p.e_i0))
    problems.push_back({"e_i0", "must exceed e_c0 (" + format_number(p.e_c0) + "), got " +
                                    format_number(p.e_i0)});
  return problems;
}

}  // namespace feedflow
