#include "models/hopper/hopper_evaluation.hpp"

#include "models/units/quantity_format.hpp"

namespace feedflow {

HopperEvaluation evaluate_hopper(const Hopper& h, double theta, double width, const HopperMaterial& m,
                                 const MaterialVariant& v, const HopperModels& models) {
  const FlowGeometry g = flow_geometry(h);
  HopperEvaluation e;
  e.flow_factor = models.flow_factor->evaluate(g, theta, v.effective_friction_angle, v.wall_friction_angle);
  const FlowFunction ff_curve = scaled_flow_function(m.flow, v.strength_scale);
  // The arching models take the material's calibrated strength where one applies.
  bool arching_calibrated = false;
  const double arching_scale = arching_strength_scale(
      m, g, models.flow_factor->name, models.critical_outlet->name, &arching_calibrated);
  const FlowFunction arching_ff =
      arching_calibrated ? scaled_flow_function(m.flow, v.strength_scale * arching_scale)
                         : ff_curve;
  e.jenike = jenike_critical_outlet(g, theta, e.flow_factor, arching_ff, m.density);
  if (g == FlowGeometry::plane)
    e.static_arch = static_arch_critical_outlet(theta, v.wall_friction_angle, e.flow_factor,
                                                arching_ff, m.density);
  CriticalWidth critical = models.critical_outlet->evaluate(e.jenike, e.static_arch);
  e.critical_width = critical.width;
  e.critical_model = std::move(critical.model);
  if (arching_calibrated)
    e.critical_model +=
        ", sigma_c x " + format_number(arching_scale, 3) + " " + m.arching_calibration->source;

  e.johanson = johanson_discharge(g, theta, width, e.flow_factor, ff_curve, m.density);
  const DischargeInputs in{g, theta, width, e.johanson, m.median_size.value_or(0.0), v.effective_friction_angle,
                           v.wall_friction_angle};
  const auto evaluate_row = [&](const DischargeModel& row) {
    bool calibrated = false;
    auto rate = row.evaluate(in, coefficients_for(row, g, m.discharge_calibration, &calibrated));
    if (rate && calibrated) rate->model += ", " + m.discharge_calibration->source;
    return rate;
  };
  e.rate_row = models.discharge;
  auto discharge = evaluate_row(*e.rate_row);
  if (!discharge) {
    e.rate_row = &discharge_models().default_row();
    discharge = evaluate_row(*e.rate_row);
  }
  e.rate = discharge->rate;
  e.rate_model = std::move(discharge->model);
  if (m.particle_density && m.median_size) {
    e.drag_factor = air_drag_factor(g, theta, width, AirDrag{*m.particle_density, *m.median_size});
    e.rate *= e.drag_factor;
    e.rate_model += ", Carleton air drag";
  }
  return e;
}

}  // namespace feedflow
