#include "designer/simulate/cel_chute_simulation.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

SimulationOutcome simulate_chute_with_cel(const SimulationRequest&) {
  throw NotAvailable("the CEL-FEM chute scene is not yet available in this build (issue 7)");
}

}  // namespace feedflow
