#pragma once
// The inclined plane on the particle rung (L3): a periodic slab across the ramp, the bin on its
// upper end rain-filled against the closed gate and settled, then the gate opened; sampled
// every 20 ms (kinetic energy, particles, mass off the ramp's end, the front); stopped once the
// kinetic energy shows the flow has stopped (unless --time is given); measured: the deposit
// profile and its mid-ramp thickness (the seed's DEM measure: the highest particle). Particle
// snapshots by default 20-50 over the run (dem_snapshot_interval), each on a row of the series.
#include <memory>

#include "designer/simulate/scene_adapter.hpp"

namespace feedflow {

// A case with [dem] stopping_layer gets the stopping layer's adapter (dem_layer_adapter.hpp).
std::unique_ptr<SceneAdapter> dem_chute_adapter(const SimulationRequest& request);

}  // namespace feedflow
