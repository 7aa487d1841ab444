#pragma once
// The pilot wedge hopper on the particle rung (L3): the one-layer slab of dem_hopper_scene,
// rain-filled and opened; sampled every 10 ms (discharged mass after the opening, particles
// and mass in the domain, kinetic energy); stopped once the steady rate's 95 % interval is
// within +-5 %, or the hopper arches or empties; measured: q_m with its interval scaled to the
// slot length, arching, the flow pattern from the layer bands (FIFO index). Particle snapshots
// by default 20-50 over the run (dem_snapshot_interval), each on a row of the series.
#include <memory>

#include "designer/simulate/scene_adapter.hpp"

namespace feedflow {

std::unique_ptr<SceneAdapter> dem_hopper_adapter(const SimulationRequest& request);

}  // namespace feedflow
