#pragma once
// The CEL-FEM verification of a hopper case: scene, run and measurements.
#include "designer/simulate/simulation_request.hpp"

namespace feedflow {

SimulationOutcome simulate_hopper_with_cel(const SimulationRequest& request);

}  // namespace feedflow
