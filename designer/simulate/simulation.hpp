#pragma once
// A full simulation of a case (`feedflow simulate`): the scene of the case's equipment on the
// request's solver (DEM rung L3 or CEL-FEM rung L2, equipment_registry.hpp), run with progress,
// snapshots and checkpoints in the request's output folder, measured and judged.
#include "designer/simulate/simulation_request.hpp"

namespace feedflow {

// Throws InputError for a case the scene cannot be set up for, NumericalFailure on a blow-up.
SimulationOutcome simulate(const SimulationRequest& request);

}  // namespace feedflow
