#pragma once
// Grid-node kinematic contact with rigid walls and Coulomb friction (models.md 2.6, option C1,
// as for rigid walls in MPM): after the free velocity update every node with mass closer to a
// wall than the contact distance d_c loses the velocity component into the wall (relative to the
// wall's own velocity); the tangential component sticks if |v_t| <= mu |v_n| and is otherwise
// reduced by mu |v_n| (no slip: always sticks). The wall reaction m (v* - v) / dt is booked per
// wall. Empty cells whose centre lies at least kWallCellCentreDepth cells inside the walls (or
// all four of whose corners do) are solid (no material, no transport), so a sliver (a cell
// mostly inside a wall) never takes material. A cut cell whose centre is less deep stays open:
// the fill gives it no material (its centre is inside), but the flow may. Marking those solid too
// left the wedge's outlet corner cell (its centre 0.18 cells deep) with a node of one open cell,
// and the settling bed circulated there without end. No penalty parameter, no time-step
// restriction.
#include <cstddef>
#include <vector>

#include "fullsim/cel/cel_fields.hpp"
#include "fullsim/cel/rigid_wall.hpp"

namespace feedflow::cel {

// How deep inside a wall an empty cell's centre lies, in cells, for the cell to be solid.
inline constexpr double kWallCellCentreDepth = 0.25;

struct WallContactOptions {
  double contact_distance = 0.5;  // d_c as a fraction of the cell size h
};

// The walls present at time t.
std::vector<PlacedWall> place_walls(const std::vector<RigidWall>& walls, double t);

// Smallest signed distance of x to the placed walls (+infinity without walls) [m].
double distance_to_walls(const std::vector<PlacedWall>& walls, const Eigen::Vector2d& x);

// Applies the contact to the nodes heavier than void_node_mass; returns the reaction force of
// each placed wall on the material (same order as `walls`) [N/m].
std::vector<NodeVector> apply_wall_contact(const CelGrid& grid,
                                           const std::vector<PlacedWall>& walls,
                                           const WallContactOptions& options, double dt,
                                           double void_node_mass, NodeFields& nodes);

// Marks empty cells whose centre is kWallCellCentreDepth cells or more, or all four of whose
// corners are, inside the walls kSolidInsideWall and releases wall cells no longer inside
// (moved or removed walls); kSolidFixed cells stay.
void mark_wall_cells(const CelGrid& grid, const std::vector<PlacedWall>& walls,
                     CellFields& cells);

}  // namespace feedflow::cel
