#pragma once
// The hopper models evaluated for one set of material values: flow factor, critical outlet
// widths and discharge. The design check evaluates it for the nominal values and for the
// corners of the material's uncertainty, and the charts sweep it over the geometry.
#include <optional>
#include <string>
#include <vector>

#include "designer/design/model_choices.hpp"
#include "models/equipment/hopper.hpp"
#include "models/hopper/critical_outlet.hpp"
#include "models/hopper/discharge_rate.hpp"
#include "models/hopper/flow_function.hpp"
#include "models/material/material.hpp"

namespace feedflow {

// What the hopper models take from the material, with the model choices applied.
struct HopperMaterial {
  FlowProperties flow;
  BulkDensity density = BulkDensity::constant(1.0);
  std::string density_model;                 // for the report
  std::optional<double> median_size;         // d50 [m]
  std::optional<double> largest_size;        // d90, taken as d_max [m]
  std::optional<double> particle_density;    // envelope density, for the air-drag correction

  // Throws InputError when the material lacks the [flow_properties] section.
  static HopperMaterial of(const Material& m, const ModelChoices& models);
};

// One corner of the uncertainty box.
struct MaterialVariant {
  double effective_friction_angle;  // delta [rad]
  double wall_friction_angle;       // phi_w [rad]
  double strength_scale;            // multiplies sigma_c
};

// The nominal variant first, then the corners (each value at -, 0, + its uncertainty).
std::vector<MaterialVariant> material_variants(const HopperMaterial& m, double wall_friction_angle,
                                               bool corners_only = false);

struct HopperEvaluation {
  double flow_factor = 0.0;
  CriticalOutlet jenike;
  std::optional<CriticalOutlet> static_arch;  // plane hoppers only
  double critical_width = 0.0;                 // by the chosen critical-outlet model [m]
  std::string critical_model;
  JohansonDischarge johanson;
  double rate = 0.0;        // chosen discharge model, per metre (wedge) or total (cone), with air drag
  double drag_factor = 1.0;
  std::string rate_model;
};

HopperEvaluation evaluate_hopper(const Hopper& h, double semi_angle, double outlet_width,
                                 const HopperMaterial& m, const MaterialVariant& v,
                                 const ModelChoices& models);

FlowFunction scaled_flow_function(const FlowProperties& p, double scale);

}  // namespace feedflow
