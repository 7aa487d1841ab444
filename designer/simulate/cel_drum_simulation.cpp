#include "designer/simulate/cel_drum_simulation.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

SimulationOutcome simulate_drum_with_cel(const SimulationRequest&) {
  throw NotAvailable("the CEL-FEM drum scene is not yet available in this build (issue 7)");
}

}  // namespace feedflow
