#pragma once
// The rotating drum on the continuum rung (L2): a plane-strain section filled and settled, then
// solved in the shell's turning frame; sampled every 20 ms (the surface angle, kinetic energy,
// mass); measured: the dynamic angle of repose, time-averaged over the second half of the run.
#include <memory>

#include "designer/simulate/scene_adapter.hpp"

namespace feedflow {

std::unique_ptr<SceneAdapter> cel_drum_adapter(const SimulationRequest& request);

}  // namespace feedflow
