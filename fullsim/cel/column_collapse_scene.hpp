#pragma once
// The CEL scene of a plane-strain granular column collapse (issue 7 validation; Lube et al.
// 2005, Lajeunesse et al. 2005): a column of length L0 (from a free-slip back wall, the left box
// face: a symmetry plane, i.e. half of a column 2 L0 wide) and height H0 = a L0 on a no-slip
// (rough) base, held by a frictionless gate at x = L0 during the gravity phase; the gate is
// removed at the event and the column spreads to the right. `runout` measures the deposit's
// front: where the thickness sum h vf along the base falls to half a cell.
#include "fullsim/cel/cel_scene.hpp"

namespace feedflow::cel {

struct ColumnCollapse {
  double aspect_ratio = 1.0;    // a = H0 / L0 [-]
  double column_length = 0.1;   // L0 [m], a multiple of the cell size
  double runout_room = 3.0;     // grid length beyond the gate in units of L0 (1 + ...)
};

CelScene make_column_collapse_scene(const ColumnCollapse& column, const SceneMaterial& material,
                                    double cell_size);

// The deposit's front [m from the back wall]: the first point, going right from the back wall,
// where the column thickness falls below h/2 (linear between column centres).
double runout(const CelSolver& solver);

}  // namespace feedflow::cel
