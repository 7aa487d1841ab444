#include "designer/simulate/solver_choice.hpp"

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
  switch (c.kind()) {
    case EquipmentKind::drum:
      return {Solver::dem,
              "DEM chosen: a laboratory drum is a small system, where the seed found particles "
              "as cheap as the continuum (about 2x) and closer to the experiment"};
    case EquipmentKind::hopper:
      return {Solver::cel,
              "CEL-FEM chosen: the seed's rule puts pilot and industrial hoppers on the "
              "continuum (same cost as a one-layer DEM slab, no slab scaling of the mass)"};
    case EquipmentKind::chute:
      return {Solver::cel,
              "CEL-FEM chosen: the seed found the continuum about 40x cheaper than DEM on the "
              "full-scale inclined plane"};
  }
  return {Solver::dem, ""};
}

}  // namespace feedflow
