#include "fullsim/cel/wall_contact.hpp"

#include <cmath>
#include <limits>

namespace feedflow::cel {

std::vector<PlacedWall> place_walls(const std::vector<RigidWall>& walls, double t) {
  std::vector<PlacedWall> placed;
  placed.reserve(walls.size());
  for (const auto& w : walls)
    if (w.present(t)) placed.emplace_back(w, t);
  return placed;
}

double distance_to_walls(const std::vector<PlacedWall>& walls, const Eigen::Vector2d& x) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& w : walls) d = std::min(d, w.signed_distance(x));
  return d;
}

namespace {

// The Coulomb projection of one relative velocity on a wall with unit normal n.
NodeVector project(const NodeVector& v_rel, const NodeVector& n, const RigidWall& wall) {
  const double vn = v_rel.dot(n);
  if (vn >= 0.0) return v_rel;  // separating or sliding along: no contact force
  NodeVector vt = v_rel - vn * n;
  const double speed = vt.norm();
  if (wall.no_slip || speed <= wall.friction * -vn) return NodeVector::Zero();
  return vt * (1.0 - wall.friction * -vn / speed);
}

}  // namespace

std::vector<NodeVector> apply_wall_contact(const CelGrid& grid,
                                           const std::vector<PlacedWall>& walls,
                                           const WallContactOptions& options, double dt,
                                           double void_node_mass, NodeFields& nodes) {
  std::vector<NodeVector> reaction(walls.size(), NodeVector::Zero());
  if (walls.empty()) return reaction;
  const double d_c = options.contact_distance * grid.cell_size;
  for (std::size_t a = 0; a < grid.node_count(); ++a) {
    if (nodes.mass[a] <= void_node_mass) continue;
    const Eigen::Vector2d x = grid.node_position(a);
    for (std::size_t k = 0; k < walls.size(); ++k) {
      NodeVector n;
      if (walls[k].signed_distance(x, &n) >= d_c) continue;
      const NodeVector vw = walls[k].velocity_at(x);
      const NodeVector before = nodes.velocity[a];
      nodes.velocity[a] = vw + project(before - vw, n, walls[k].wall());
      reaction[k] += nodes.mass[a] * (nodes.velocity[a] - before) / dt;
    }
  }
  return reaction;
}

void mark_wall_cells(const CelGrid& grid, const std::vector<PlacedWall>& walls,
                     CellFields& cells) {
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    if (cells.solid[c] == kSolidFixed) continue;
    // An empty cell whose centre is a quarter cell or more inside the walls, or all of whose
    // corners are.
    bool inside = !walls.empty() && cells.mass[c] <= 0.0;
    if (inside && distance_to_walls(walls, grid.cell_centre(c)) > -kWallCellCentreDepth * grid.cell_size)
      for (std::size_t a : grid.cell_nodes(c)) {
        if (!inside) break;
        inside = distance_to_walls(walls, grid.node_position(a)) <= 0.0;
      }
    cells.solid[c] = inside ? kSolidInsideWall : 0;
  }
}

}  // namespace feedflow::cel
