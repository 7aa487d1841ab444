#include "models/hopper/discharge_models.hpp"

#include <numbers>

#include "models/hopper/flow_pattern.hpp"
#include "models/hopper/minimum_energy_discharge.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::optional<DischargeRate> johanson(const DischargeInputs& in) {
  return DischargeRate{in.johanson.rate, "Johanson with the cohesion factor"};
}

std::optional<DischargeRate> beverloo(const DischargeInputs& in) {
  const double rho = in.johanson.bulk_density;
  if (in.geometry == FlowGeometry::plane)
    return DischargeRate{beverloo_slot_rate_per_metre(rho, in.outlet_width, in.median_size),
                         "Beverloo slot (C2 = 1.03, k = 1.5, d = d50)"};
  return DischargeRate{beverloo_circular_rate(rho, in.outlet_width, in.median_size),
                       "Beverloo circular (C = 0.58, k = 1.5, d = d50)"};
}

std::optional<DischargeRate> brown(const DischargeInputs& in) {
  if (in.geometry != FlowGeometry::plane) return std::nullopt;
  return DischargeRate{brown_richards_rate_per_metre(in.johanson.bulk_density, in.outlet_width, in.semi_angle),
                       "Brown-Richards minimum energy (wedge)"};
}

// Beverloo with Rose & Tanaka's hopper factor, the stagnant zone standing at the flow-pattern
// boundary (phi_d = 90 deg - the mass-flow limit): F = 1 in funnel flow.
std::optional<DischargeRate> rose_tanaka(const DischargeInputs& in) {
  const double limit = mass_flow_limit(in.geometry, in.effective_friction_angle, in.wall_friction_angle).nominal;
  const double f = rose_tanaka_factor(in.semi_angle, 0.5 * std::numbers::pi - limit);
  const DischargeRate flat = *beverloo(in);
  return DischargeRate{f * flat.rate, flat.model + " x Rose-Tanaka F = " + format_number(f, 3)};
}

constexpr DischargeModel kRows[] = {
    {{"johanson", Rung::L0, "Johanson (1965) with the cohesion factor: mass flow, cohesive solids"},
     &johanson, "Johanson (cohesive)", true},
    {{"beverloo", Rung::L0, "Beverloo (1961) empirical correlation, k = 1.5, d = d50: flat-bottomed or funnel flow"},
     &beverloo, "Beverloo", true},
    {{"brown", Rung::L0, "Brown & Richards minimum-energy theory (wedge hoppers only)"}, &brown, "Brown-Richards",
     true},
    // Not in the band: it refines the Beverloo row for the hopper's walls, not another view.
    {{"rose_tanaka", Rung::L0, "Beverloo x Rose & Tanaka's (1956) hopper factor (tan theta tan phi_d)^-0.35, "
                               "phi_d = 90 deg - the mass-flow limit"},
     &rose_tanaka, "Beverloo x Rose-Tanaka", false},
};

constexpr ModelTable<DischargeModel> kTable{"hopper.discharge", "discharge rate", kRows};

}  // namespace

const ModelTable<DischargeModel>& discharge_models() { return kTable; }

}  // namespace feedflow
