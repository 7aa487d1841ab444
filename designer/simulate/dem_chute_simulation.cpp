#include "designer/simulate/dem_chute_simulation.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

SimulationOutcome simulate_chute_with_dem(const SimulationRequest&) {
  throw NotAvailable("the DEM chute scene is not yet available in this build (issue 6)");
}

}  // namespace feedflow
