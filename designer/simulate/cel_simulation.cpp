#include "designer/simulate/cel_simulation.hpp"

#include "designer/simulate/cel_chute_simulation.hpp"
#include "designer/simulate/cel_drum_simulation.hpp"
#include "designer/simulate/cel_hopper_simulation.hpp"

namespace feedflow {

SimulationOutcome simulate_with_cel(const SimulationRequest& request) {
  switch (request.case_data.kind()) {
    case EquipmentKind::hopper: return simulate_hopper_with_cel(request);
    case EquipmentKind::chute: return simulate_chute_with_cel(request);
    case EquipmentKind::drum: return simulate_drum_with_cel(request);
  }
  return simulate_hopper_with_cel(request);
}

}  // namespace feedflow
