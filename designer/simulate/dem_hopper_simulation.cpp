#include "designer/simulate/dem_hopper_simulation.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

SimulationOutcome simulate_hopper_with_dem(const SimulationRequest&) {
  throw NotAvailable("the DEM hopper scene is not yet available in this build (issue 6)");
}

}  // namespace feedflow
