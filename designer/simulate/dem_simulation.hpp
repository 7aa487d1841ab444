#pragma once
// The DEM verification of a case (rung L3): builds the case's scene, runs it with progress,
// snapshots and checkpoints in the request's output folder, and measures the design quantities.
#include "designer/simulate/simulation_request.hpp"

namespace feedflow {

// Throws InputError for a case the solver cannot set up, NumericalFailure on a blow-up.
SimulationOutcome simulate_with_dem(const SimulationRequest& request);

}  // namespace feedflow
