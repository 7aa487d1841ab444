#include "designer/simulate/dem_simulation.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

SimulationOutcome simulate_with_dem(const SimulationRequest& request) {
  throw NotAvailable(std::string("the DEM scene for a ") + to_string(request.case_data.kind()) +
                     " is not yet available in this build (issue 6)");
}

}  // namespace feedflow
