#include "designer/simulate/cel_simulation.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

SimulationOutcome simulate_with_cel(const SimulationRequest& request) {
  throw NotAvailable(std::string("the CEL-FEM scene for a ") + to_string(request.case_data.kind()) +
                     " is not yet available in this build (issue 7)");
}

}  // namespace feedflow
