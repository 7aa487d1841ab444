#pragma once
// The rotating drum on the particle rung (L3): a periodic axial slab (or the full 3D drum with
// turning end plates) rain-filled to the fill line and settled, then the shell turning; sampled
// every 20 ms (the surface angle, the bed state); stopped once the mean angle of the last two
// windows agrees within 1 deg (unless --time is given); measured: the dynamic angle of repose
// with a 2 SD band and the regime from the measured bed state. Particle snapshots by default
// 20-50 over the run (dem_snapshot_interval), each on a row of the series.
#include <memory>

#include "designer/case/case.hpp"
#include "designer/simulate/scene_adapter.hpp"
#include "fullsim/dem/scene/drum_scene.hpp"

namespace feedflow {

std::unique_ptr<SceneAdapter> dem_drum_adapter(const SimulationRequest& request);

// The scene the adapter builds for a drum case: its DEM settings (a slab's shell takes the case's
// wall friction), its spec (throws InputError naming the key for a case it cannot build), and the
// rotation it runs at most when no --time is given [s] (dem.end_time, else the seed's 10 s).
DemSettings dem_drum_settings(const Case& c, const DemRanks& ranks = DemRanks::one());
DrumSceneSpec dem_drum_spec(const Case& c, const DemSettings& settings);
double dem_drum_rotation(const Case& c);

}  // namespace feedflow
