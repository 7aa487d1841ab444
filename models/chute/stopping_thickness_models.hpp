#pragma once
// The stopping-thickness models of a chute (`--model chute.stopping_thickness=NAME`): the
// thickness of the layer that stays on the ramp at an angle, from the material's Pouliquen law.
#include "models/chute/pouliquen_law.hpp"
#include "models/core/model_table.hpp"
#include "models/material/material.hpp"

namespace feedflow {

// `m` has [surface_flow]; `law` is its Pouliquen law (or a corner of its uncertainty).
using StoppingThicknessEvaluate = StoppingThickness (*)(const PouliquenLaw& law, const Material& m, double angle);
using StoppingThicknessModel = ModelRow<StoppingThicknessEvaluate>;

// pouliquen (default), hybrid. A row's summary is the model text of the stopping_thickness
// estimate.
const ModelTable<StoppingThicknessModel>& stopping_thickness_models();

}  // namespace feedflow
