#pragma once
// The four faces of the grid box as velocity boundary conditions on their nodes (models.md 2.3
// item 5, 2.4 item 6, 2.6): free slip (symmetry: zero normal velocity), no slip (zero velocity),
// open (no constraint, no flux: material reaching the face stays in the grid) or outflow (no
// constraint; material crossing the face in the remap leaves the grid and its mass is booked,
// Abaqus' outflow ZERO PRESSURE; only void enters). Cells fixed solid fix all their nodes.
#include "fullsim/cel/cel_fields.hpp"

namespace feedflow::cel {

enum class WallCondition { open, free_slip, no_slip, outflow };

struct BoxWalls {
  WallCondition left = WallCondition::free_slip;
  WallCondition right = WallCondition::free_slip;
  WallCondition bottom = WallCondition::no_slip;
  WallCondition top = WallCondition::open;
};

// Sets NodeFields::constraint from the box faces and the solid cells.
void assign_node_constraints(const CelGrid& grid, const BoxWalls& walls,
                             const CellFields& cells, NodeFields& nodes);

// Zeroes the prescribed velocity components of every node.
void apply_node_constraints(NodeFields& nodes);

}  // namespace feedflow::cel
