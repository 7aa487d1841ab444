#pragma once
// `feedflow simulate` for any equipment and rung: the adapter builds the scene (or its
// structure, restored from the checkpoint), the scene run loop runs it, the adapter measures,
// the reduced-model values go beside the measured ones, the equipment's judge gives the verdict
// and the adapter explains (charts, assumptions).
#include "designer/simulate/scene_adapter.hpp"

namespace feedflow {

SimulationOutcome simulate_scene(SceneAdapter& adapter, const SimulationRequest& request);

}  // namespace feedflow
