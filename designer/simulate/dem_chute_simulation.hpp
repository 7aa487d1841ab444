#pragma once
// The DEM verification of a chute case: scene, run and measurements.
#include "designer/simulate/simulation_request.hpp"

namespace feedflow {

SimulationOutcome simulate_chute_with_dem(const SimulationRequest& request);

}  // namespace feedflow
