#pragma once
// The DEM verification of a drum case: scene, run and measurements.
#include "designer/simulate/simulation_request.hpp"

namespace feedflow {

SimulationOutcome simulate_drum_with_dem(const SimulationRequest& request);

}  // namespace feedflow
