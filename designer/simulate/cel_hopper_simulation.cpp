#include "designer/simulate/cel_hopper_simulation.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

SimulationOutcome simulate_hopper_with_cel(const SimulationRequest&) {
  throw NotAvailable("the CEL-FEM hopper scene is not yet available in this build (issue 7)");
}

}  // namespace feedflow
