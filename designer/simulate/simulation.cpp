#include "designer/simulate/simulation.hpp"

#include "designer/equipment/equipment_registry.hpp"
#include "designer/simulate/scene_simulation.hpp"

namespace feedflow {

SimulationOutcome simulate(const SimulationRequest& request) {
  const EquipmentEntry& equipment = equipment_of(request.case_data.kind());
  const auto adapter = request.solver == Solver::dem ? equipment.dem(request) : equipment.cel(request);
  return simulate_scene(*adapter, request);
}

}  // namespace feedflow
