#include "designer/simulate/dem_simulation.hpp"

#include "designer/simulate/dem_chute_simulation.hpp"
#include "designer/simulate/dem_drum_simulation.hpp"
#include "designer/simulate/dem_hopper_simulation.hpp"

namespace feedflow {

SimulationOutcome simulate_with_dem(const SimulationRequest& request) {
  switch (request.case_data.kind()) {
    case EquipmentKind::hopper: return simulate_hopper_with_dem(request);
    case EquipmentKind::chute: return simulate_chute_with_dem(request);
    case EquipmentKind::drum: return simulate_drum_with_dem(request);
  }
  return simulate_hopper_with_dem(request);
}

}  // namespace feedflow
