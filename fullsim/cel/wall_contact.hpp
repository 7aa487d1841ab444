#pragma once
// Grid-node kinematic contact with rigid walls and Coulomb friction (models.md 2.6, option C1,
// as for rigid walls in MPM): after the free velocity update every node with mass closer to a
// wall than the contact distance d_c loses the velocity component into the wall (relative to the
// wall's own velocity); the tangential component sticks if |v_t| <= mu |v_n| and is otherwise
// reduced by mu |v_n| (no slip: always sticks). The wall reaction m (v* - v) / dt is booked per
// wall. A node touching two walls (a corner) takes the nearest velocity that moves into neither,
// then friction on the one wall it slides along, if any. No penalty parameter, no time-step
// restriction.
//
// The grid sees an inclined wall as a staircase of solid cells: empty cells whose centre lies
// inside the walls (or all four of whose corners do) take no material and no transport, so a
// sliver (a cell mostly inside a wall) never fills. A corner of such a cell can lie up to 0.71
// cells from the wall on the material side, beyond d_c, so every node of a solid cell is also
// held by its nearest wall: no node moves into the staircase. Without that hold, the cut cell at
// a wedge's outlet edge kept a free node and the settling bed circulated there without end; with
// solid cells only from a quarter cell deep instead, cut cells less deep filled and slid along a
// 40 deg cone's wall at twice the centre line's speed.
#include <cstddef>
#include <vector>

#include "fullsim/cel/cel_fields.hpp"
#include "fullsim/cel/rigid_wall.hpp"

namespace feedflow::cel {

struct WallContactOptions {
  double contact_distance = 0.5;  // d_c as a fraction of the cell size h
};

// The walls present at time t.
std::vector<PlacedWall> place_walls(const std::vector<RigidWall>& walls, double t);

// Smallest signed distance of x to the placed walls (+infinity without walls) [m].
double distance_to_walls(const std::vector<PlacedWall>& walls, const Eigen::Vector2d& x);

// Applies the contact to the nodes heavier than void_node_mass (within d_c of a wall, or a
// corner of a cell marked kSolidInsideWall); returns the reaction force of each placed wall on
// the material (same order as `walls`) [N/m].
std::vector<NodeVector> apply_wall_contact(const CelGrid& grid,
                                           const std::vector<PlacedWall>& walls,
                                           const WallContactOptions& options, double dt,
                                           double void_node_mass, const CellFields& cells,
                                           NodeFields& nodes);

// Marks empty cells whose centre, or all four of whose corners, lie inside the walls
// kSolidInsideWall and releases wall cells no longer inside
// (moved or removed walls); kSolidFixed cells stay.
void mark_wall_cells(const CelGrid& grid, const std::vector<PlacedWall>& walls,
                     CellFields& cells);

}  // namespace feedflow::cel
