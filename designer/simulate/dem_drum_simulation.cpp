#include "designer/simulate/dem_drum_simulation.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

SimulationOutcome simulate_drum_with_dem(const SimulationRequest&) {
  throw NotAvailable("the DEM drum scene is not yet available in this build (issue 6)");
}

}  // namespace feedflow
