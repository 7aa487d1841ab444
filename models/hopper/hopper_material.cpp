#include "models/hopper/hopper_material.hpp"

#include <algorithm>
#include <cstdlib>
#include <numbers>
#include <string_view>
#include <utility>

#include "models/core/errors.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

// The row with the smallest `figure` among the fitted rows; empty when no row has it.
std::pair<std::string, std::string> best_by(const Calibration& c, const std::string& figure) {
  std::pair<std::string, std::string> best;
  double lowest = 0.0;
  for (const auto& [row, fitted] : c.discharge) {
    const auto x = percent_figure(fitted, figure);
    if (x && (best.first.empty() || *x < lowest)) {
      lowest = *x;
      best = {row, fitted.figures.at(figure)};
    }
  }
  return best;
}

}  // namespace

HopperMaterial HopperMaterial::of(const Material& m, const HopperDensityModel& density) {
  if (!m.flow)
    throw InputError(m.origin, "material.flow_properties",
                     "the hopper models need the material's flow function and effective angle "
                     "of internal friction ([flow_properties]); material " + m.name + " has none");
  HopperMaterial hm;
  hm.flow = *m.flow;
  const auto compressibility = BulkCompressibility::of(m);
  if (compressibility) hm.particle_density = compressibility->solid_density();
  HopperDensity chosen = density.evaluate(m, compressibility);
  hm.density = std::move(chosen.density);
  hm.density_model = std::move(chosen.model);
  if (m.psd) {
    hm.median_size = m.psd->d50;
    hm.largest_size = m.psd->d90;
  }
  if (m.calibration && !m.calibration->discharge.empty()) {
    const Calibration& c = *m.calibration;
    if (c.density_model != density.name) {
      hm.calibration_note = "the material's calibrated discharge coefficients are not used: they were fitted with "
                            "hopper.bulk_density=" + c.density_model + ", this check uses " + std::string(density.name);
    } else {
      DischargeCalibration dc;
      dc.geometry = c.geometry == "conical" ? FlowGeometry::conical : FlowGeometry::plane;
      dc.source = "calibrated against " + c.rung.substr(0, c.rung.find(',')) + " (" + c.scene + ", " + c.date + ")";
      for (const auto& [row_name, fitted] : c.discharge) {
        const DischargeModel& row = discharge_models().at(row_name);  // the reader checked the names
        std::vector<double> values;
        for (const auto& k : row.coefficients) values.push_back(fitted.coefficients.at(std::string(k.name)));
        dc.coefficients.emplace(row_name, std::move(values));
        if (const auto error = largest_error(fitted)) dc.row_error[row_name] = *error;
      }
      auto best = best_by(c, "held_out_max_error");
      if (!best.first.empty()) {
        best.second = "held-out max error " + best.second;
      } else {
        best = best_by(c, "fit_rms_error");
        if (!best.first.empty()) best.second = "fit rms error " + best.second;
      }
      dc.best_row = best.first;
      dc.best_row_error = best.second;
      hm.discharge_calibration = std::move(dc);
    }
  }
  if (m.calibration && m.calibration->arching) {
    const ArchingCalibration& a = *m.calibration->arching;
    ArchingScale scale;
    scale.geometry = a.geometry == "conical" ? FlowGeometry::conical : FlowGeometry::plane;
    scale.flow_factor = a.flow_factor;
    for (const auto& [row, fitted] : a.rows)
      scale.strength_scale[row] = fitted.coefficients.at("strength_scale");
    scale.source = "calibrated against " + a.rung.substr(0, a.rung.find(',')) + " (" + a.scene +
                   ", " + a.date + ")";
    hm.arching_calibration = std::move(scale);
  }
  return hm;
}

double arching_strength_scale(const HopperMaterial& m, FlowGeometry g, std::string_view flow_factor,
                              std::string_view critical_outlet, bool* calibrated) {
  if (calibrated) *calibrated = false;
  const auto& a = m.arching_calibration;
  if (!a || a->geometry != g || a->flow_factor != flow_factor) return 1.0;
  const auto it = a->strength_scale.find(critical_outlet);
  if (it == a->strength_scale.end()) return 1.0;
  if (calibrated) *calibrated = true;
  return it->second;
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
                                        1.0 * kDegree, 89.0 * kDegree);
        // The wall cannot be rougher than the material's internal friction.
        const double wall = std::clamp(phi_w + b * f.wall_friction_uncertainty, 0.0, delta - 0.5 * kDegree);
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

}  // namespace feedflow
