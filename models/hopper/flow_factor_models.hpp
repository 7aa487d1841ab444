#pragma once
// The flow-factor models (`--model hopper.flow_factor=NAME`): the hopper's flow factor ff at a
// semi-angle from the effective angle of internal friction and the wall friction angle.
#include "models/core/model_table.hpp"
#include "models/hopper/hopper_geometry.hpp"

namespace feedflow {

using FlowFactorEvaluate = double (*)(FlowGeometry g, double semi_angle, double effective_friction_angle,
                                      double wall_friction_angle);
using FlowFactorModel = ModelRow<FlowFactorEvaluate>;

// enstad (default), rsf. A row's summary is the model text of the flow_factor estimate.
const ModelTable<FlowFactorModel>& flow_factor_models();

}  // namespace feedflow
