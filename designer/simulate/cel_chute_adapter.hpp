#pragma once
// The inclined plane on the continuum rung (L2): a plane-strain slice along the ramp, the bin
// filled and settled, the gate lifted; sampled every 20 ms (kinetic energy, mass on the grid,
// run-off, the mid-ramp thickness); stopped once the kinetic energy is below 1e-4 of its peak
// after the release; measured: the deposit profile and its mid-ramp thickness (the seed's FEM
// measure: sum of cell heights x volume fraction).
#include <memory>

#include "designer/simulate/scene_adapter.hpp"

namespace feedflow {

// [m] the chute's cells when [cel] cell_size is not given.
inline constexpr double kCelChuteCellSize = 0.02;

std::unique_ptr<SceneAdapter> cel_chute_adapter(const SimulationRequest& request);

}  // namespace feedflow
