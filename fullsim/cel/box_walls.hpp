#pragma once
// The four faces of the grid box as velocity boundary conditions on their nodes (models.md 2.3
// item 5, 2.6): free slip (symmetry: zero normal velocity), no slip (zero velocity) or open (no
// constraint; with no outflow boundary yet, material stays in the grid: the remap has no flux
// through the box faces). Cells marked solid fix all their nodes (no slip).
#include "fullsim/cel/cel_fields.hpp"

namespace feedflow::cel {

enum class WallCondition { open, free_slip, no_slip };

struct BoxWalls {
  WallCondition left = WallCondition::free_slip;
  WallCondition right = WallCondition::free_slip;
  WallCondition bottom = WallCondition::no_slip;
  WallCondition top = WallCondition::open;
};

// Sets NodeFields::constraint from the box faces and the solid cells.
void assign_node_constraints(const PlaneStrainGrid& grid, const BoxWalls& walls,
                             const CellFields& cells, NodeFields& nodes);

// Zeroes the prescribed velocity components of every node.
void apply_node_constraints(NodeFields& nodes);

}  // namespace feedflow::cel
