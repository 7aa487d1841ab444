#pragma once
// The discharge-rate models (`--model hopper.discharge=NAME`): the steady mass flow rate of the
// hopper's outlet, per metre of slot (wedge) or total (cone), before the air-drag correction.
// The rate's band spans the rows that say so, at the nominal material values.
#include <optional>
#include <string>
#include <string_view>

#include "models/core/model_table.hpp"
#include "models/hopper/discharge_rate.hpp"

namespace feedflow {

struct DischargeInputs {
  FlowGeometry geometry;
  double semi_angle;                  // theta [rad]
  double outlet_width;                // B [m]
  const JohansonDischarge& johanson;  // its rate, and rho_b at the outlet stress
  double median_size;                 // d50 [m]; 0 when the material has no size distribution
  double effective_friction_angle = 0.0;  // delta [rad]
  double wall_friction_angle = 0.0;       // phi_w [rad]
};

struct DischargeRate {
  double rate;        // kg/(s m) plane, kg/s conical
  std::string model;  // the model text of the mass_flow_rate estimate
};

// Nothing where the model does not apply (Brown-Richards on a cone): the default row stands in.
using DischargeEvaluate = std::optional<DischargeRate> (*)(const DischargeInputs&);

struct DischargeModel : ModelEntry {
  DischargeEvaluate evaluate;
  std::string_view legend;  // the model's curve in the rate-against-outlet chart
  bool spans_band;          // one of the alternatives the rate's band spans
};

// johanson (default), beverloo, brown, rose_tanaka.
const ModelTable<DischargeModel>& discharge_models();

}  // namespace feedflow
