#include "designer/design/hopper_assessment.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "models/core/errors.hpp"
#include "models/hopper/enstad_flow_factor.hpp"
#include "models/hopper/minimum_energy_discharge.hpp"
#include "models/hopper/radial_stress_field.hpp"
#include "models/material/bulk_compressibility.hpp"

namespace feedflow {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

HopperMaterial HopperMaterial::of(const Material& m, const ModelChoices& models) {
  if (!m.flow)
    throw InputError(m.origin, "material.flow_properties",
                     "the hopper models need the material's flow function and effective angle "
                     "of internal friction ([flow_properties]); material " + m.name + " has none");
  HopperMaterial hm;
  hm.flow = *m.flow;
  const auto compressibility = BulkCompressibility::of(m);
  if (compressibility) hm.particle_density = compressibility->solid_density();
  const auto choice = models["hopper.bulk_density"];
  const bool has_table = !hm.flow.density.empty();
  if (choice == "table" && !has_table)
    throw InputError("--model", "hopper.bulk_density",
                     "table chosen, but material " + m.name + " has no density_major_stress/density table in "
                     "[flow_properties]");
  if (choice == "compressible" && compressibility) {
    hm.density = BulkDensity::compressible(*compressibility);
    hm.density_model = "critical-state density from the Bauer compression law (hypoplastic parameters)";
  } else if (choice != "constant" && has_table) {
    hm.density = BulkDensity::tabulated(hm.flow.density_major_stress, hm.flow.density);
    hm.density_model = "measured compressibility table rho_b(sigma1)";
  } else {
    hm.density = BulkDensity::constant(m.bulk.density);
    hm.density_model = "constant design bulk density";
  }
  if (m.psd) {
    hm.median_size = m.psd->d50;
    hm.largest_size = m.psd->d90;
  }
  return hm;
}

std::vector<MaterialVariant> material_variants(const HopperMaterial& m, double phi_w, bool corners_only) {
  const auto& f = m.flow;
  std::vector<MaterialVariant> out{{f.effective_friction_angle, phi_w, 1.0}};
  const double steps[] = {-1.0, 0.0, 1.0};
  for (double a : steps)
    for (double b : steps)
      for (double c : steps) {
        if (a == 0 && b == 0 && c == 0) continue;
        if (corners_only && (a == 0 || b == 0 || c == 0)) continue;
        const double delta = std::clamp(f.effective_friction_angle + a * f.effective_friction_uncertainty,
                                        1.0 * kDeg, 89.0 * kDeg);
        // The wall cannot be rougher than the material's internal friction.
        const double wall = std::clamp(phi_w + b * f.wall_friction_uncertainty, 0.0, delta - 0.5 * kDeg);
        out.push_back({delta, wall, std::max(0.0, 1.0 + c * f.ff_uncertainty)});
      }
  return out;
}

FlowFunction scaled_flow_function(const FlowProperties& p, double k) {
  if (p.flow_function == "power_law") return FlowFunction::power_law(p.ff_coefficient * k, p.ff_exponent);
  if (p.flow_function == "tabulated") {
    std::vector<double> strength = p.ff_strength;
    for (double& s : strength) s *= k;
    return FlowFunction::tabulated(p.ff_major_stress, strength);
  }
  return FlowFunction::linear(std::min(p.ff_slope * k, 0.999), p.ff_intercept * k);
}

HopperEvaluation evaluate_hopper(const Hopper& h, double theta, double width, const HopperMaterial& m,
                                 const MaterialVariant& v, const ModelChoices& models) {
  const FlowGeometry g = flow_geometry(h);
  HopperEvaluation e;
  if (models["hopper.flow_factor"] == "rsf") {
    const auto field = solve_radial_stress_field(g, theta, v.effective_friction_angle, v.wall_friction_angle);
    // Beyond the existence limit there is no radial field (funnel flow): Enstad's closed form
    // still gives the arching estimate.
    e.flow_factor = field ? field->flow_factor
                          : enstad_flow_factor(g, theta, v.effective_friction_angle, v.wall_friction_angle);
  } else {
    e.flow_factor = enstad_flow_factor(g, theta, v.effective_friction_angle, v.wall_friction_angle);
  }
  const FlowFunction ff_curve = scaled_flow_function(m.flow, v.strength_scale);
  e.jenike = jenike_critical_outlet(g, theta, e.flow_factor, ff_curve, m.density);
  if (g == FlowGeometry::plane)
    e.static_arch = static_arch_critical_outlet(theta, v.wall_friction_angle, e.flow_factor, ff_curve, m.density);

  const auto choice = models["hopper.critical_outlet"];
  if (choice == "static_arch" && e.static_arch) {
    e.critical_width = e.static_arch->width;
    e.critical_model = e.static_arch->model;
  } else if (choice == "jenike" || !e.static_arch) {
    e.critical_width = e.jenike.width;
    e.critical_model = e.jenike.model;
  } else {
    e.critical_width = std::max(e.jenike.width, e.static_arch->width);
    e.critical_model = "envelope of Jenike H(theta) and static-arch H_a";
  }

  e.johanson = johanson_discharge(g, theta, width, e.flow_factor, ff_curve, m.density);
  const double rho_out = e.johanson.bulk_density;
  const auto discharge = models["hopper.discharge"];
  const double d = m.median_size.value_or(0.0);
  if (discharge == "beverloo") {
    e.rate = g == FlowGeometry::plane ? beverloo_slot_rate_per_metre(rho_out, width, d)
                                      : beverloo_circular_rate(rho_out, width, d);
    e.rate_model = g == FlowGeometry::plane ? "Beverloo slot (C2 = 1.03, k = 1.5, d = d50)"
                                            : "Beverloo circular (C = 0.58, k = 1.5, d = d50)";
  } else if (discharge == "brown" && g == FlowGeometry::plane) {
    e.rate = brown_richards_rate_per_metre(rho_out, width, theta);
    e.rate_model = "Brown-Richards minimum energy (wedge)";
  } else {
    e.rate = e.johanson.rate;
    e.rate_model = "Johanson with the cohesion factor";
  }
  if (m.particle_density && m.median_size) {
    e.drag_factor = air_drag_factor(g, theta, width, AirDrag{*m.particle_density, *m.median_size});
    e.rate *= e.drag_factor;
    e.rate_model += ", Carleton air drag";
  }
  return e;
}

}  // namespace feedflow
