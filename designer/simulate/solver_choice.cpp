#include "designer/simulate/solver_choice.hpp"

#include "designer/equipment/equipment_registry.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

const char* to_string(Solver solver) { return solver == Solver::dem ? "dem" : "cel"; }

Solver parse_solver(const std::string& text) {
  if (text == "dem") return Solver::dem;
  if (text == "cel") return Solver::cel;
  throw InputError("--solver", "", "unknown solver '" + text + "'; expected dem (particles, rung L3) or cel (CEL-FEM continuum, rung L2)");
}

SolverChoice choose_solver(const Case& c, std::optional<Solver> asked) {
  if (asked) return {*asked, std::string("--solver ") + to_string(*asked) + " asked for"};
  const EquipmentEntry& e = equipment_of(c.kind());
  return {e.default_solver, e.why};
}

}  // namespace feedflow
