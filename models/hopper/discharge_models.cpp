#include "models/hopper/discharge_models.hpp"

#include <numbers>

#include "models/hopper/flow_pattern.hpp"
#include "models/hopper/minimum_energy_discharge.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

// Beverloo's C (C2 for a slot: Nedderman's 1.03; a circle: 0.58) and k (1.5, d = d50); k has
// been measured between 1 and 3 for most solids (Nedderman 1992), a fit may take it to 0 (no
// empty annulus, as for a continuum) but not past 3.
constexpr DischargeCoefficient kBeverlooCoefficients[] = {
    {"c", 1.03, 0.58, 0.05, 5.0, "discharge coefficient C (C2 for a slot)"},
    {"k", kBeverlooK, kBeverlooK, 0.0, 3.0, "empty annulus k: the outlet acts k d50 narrower"},
};
// A factor on a theory's rate (1: the theory as published), within a factor of 10 either way.
constexpr DischargeCoefficient kFactor[] = {{"factor", 1.0, 1.0, 0.1, 10.0, "factor on the theory's rate"}};

// " x 1.83" for a factor other than the theory's 1.
std::string factor_text(double factor) { return factor == 1.0 ? "" : " x " + format_number(factor, 3); }

std::optional<DischargeRate> johanson(const DischargeInputs& in, std::span<const double> c) {
  return DischargeRate{c[0] * in.johanson.rate, "Johanson with the cohesion factor" + factor_text(c[0])};
}

std::optional<DischargeRate> beverloo(const DischargeInputs& in, std::span<const double> c) {
  const double rho = in.johanson.bulk_density;
  if (in.geometry == FlowGeometry::plane)
    return DischargeRate{beverloo_slot_rate_per_metre(rho, in.outlet_width, in.median_size, c[1], c[0]),
                         "Beverloo slot (C2 = " + format_number(c[0], 3) + ", k = " + format_number(c[1], 3) +
                             ", d = d50)"};
  return DischargeRate{beverloo_circular_rate(rho, in.outlet_width, in.median_size, c[1], c[0]),
                       "Beverloo circular (C = " + format_number(c[0], 3) + ", k = " + format_number(c[1], 3) +
                           ", d = d50)"};
}

std::optional<DischargeRate> brown(const DischargeInputs& in, std::span<const double> c) {
  if (in.geometry != FlowGeometry::plane) return std::nullopt;
  return DischargeRate{c[0] * brown_richards_rate_per_metre(in.johanson.bulk_density, in.outlet_width, in.semi_angle),
                       "Brown-Richards minimum energy (wedge)" + factor_text(c[0])};
}

// Beverloo with Rose & Tanaka's hopper factor, the stagnant zone standing at the flow-pattern
// boundary (phi_d = 90 deg - the mass-flow limit): F = 1 in funnel flow.
std::optional<DischargeRate> rose_tanaka(const DischargeInputs& in, std::span<const double> c) {
  const double limit = mass_flow_limit(in.geometry, in.effective_friction_angle, in.wall_friction_angle).nominal;
  const double f = rose_tanaka_factor(in.semi_angle, 0.5 * std::numbers::pi - limit);
  const DischargeRate flat = *beverloo(in, c);
  return DischargeRate{f * flat.rate, flat.model + " x Rose-Tanaka F = " + format_number(f, 3)};
}

constexpr DischargeModel kDischargeRows[] = {
    {{"johanson", Rung::L0, "Johanson (1965) with the cohesion factor: mass flow, cohesive solids"},
     &johanson,
     "Johanson (cohesive)",
     true,
     kFactor},
    {{"beverloo", Rung::L0,
      "Beverloo (1961) empirical correlation, k = 1.5, d = d50: flat-bottomed or funnel flow"},
     &beverloo,
     "Beverloo",
     true,
     kBeverlooCoefficients},
    {{"brown", Rung::L0, "Brown & Richards minimum-energy theory (wedge hoppers only)"},
     &brown,
     "Brown-Richards",
     true,
     kFactor},
    // Not in the band: it refines the Beverloo row for the hopper's walls, not another view.
    {{"rose_tanaka", Rung::L0,
      "Beverloo x Rose & Tanaka's (1956) hopper factor (tan theta tan phi_d)^-0.35, "
      "phi_d = 90 deg - the mass-flow limit"},
     &rose_tanaka,
     "Beverloo x Rose-Tanaka",
     false,
     kBeverlooCoefficients},
};

constexpr ModelTable<DischargeModel> kDischargeTable{"hopper.discharge", "discharge rate",
                                                     kDischargeRows};

}  // namespace

const ModelTable<DischargeModel>& discharge_models() { return kDischargeTable; }

std::optional<DischargeRate> DischargeModel::published(const DischargeInputs& in) const {
  return evaluate(in, published_coefficients(*this, in.geometry));
}

std::vector<double> published_coefficients(const DischargeModel& row, FlowGeometry g) {
  std::vector<double> c;
  for (const auto& k : row.coefficients) c.push_back(g == FlowGeometry::plane ? k.published_plane : k.published_conical);
  return c;
}

std::string coefficients_text(const DischargeModel& row, std::span<const double> c) {
  std::string s;
  for (std::size_t i = 0; i < row.coefficients.size() && i < c.size(); ++i)
    s += (i ? ", " : "") + std::string(row.coefficients[i].name) + " = " + format_number(c[i], 3);
  return s;
}

std::vector<double> coefficients_for(const DischargeModel& row, FlowGeometry g,
                                     const std::optional<DischargeCalibration>& calibration, bool* calibrated) {
  if (calibration && calibration->geometry == g) {
    const auto it = calibration->coefficients.find(row.name);
    if (it != calibration->coefficients.end() && it->second.size() == row.coefficients.size()) {
      if (calibrated) *calibrated = true;
      return it->second;
    }
  }
  if (calibrated) *calibrated = false;
  return published_coefficients(row, g);
}

std::optional<double> calibrated_error(const DischargeModel& row, FlowGeometry g,
                                       const std::optional<DischargeCalibration>& calibration) {
  bool calibrated = false;
  coefficients_for(row, g, calibration, &calibrated);
  if (!calibrated) return std::nullopt;
  const auto it = calibration->row_error.find(row.name);
  if (it == calibration->row_error.end()) return std::nullopt;
  return it->second;
}

}  // namespace feedflow
