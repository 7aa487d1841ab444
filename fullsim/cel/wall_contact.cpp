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

// Whether node a is a corner of a cell inside a wall.
bool corner_of_wall_cell(const CelGrid& grid, const CellFields& cells, std::size_t a) {
  const int i = grid.node_i(a), j = grid.node_j(a);
  for (int cj = j - 1; cj <= j; ++cj)
    for (int ci = i - 1; ci <= i; ++ci)
      if (ci >= 0 && cj >= 0 && ci < grid.nx && cj < grid.ny &&
          cells.solid[grid.cell(ci, cj)] == kSolidInsideWall)
        return true;
  return false;
}

}  // namespace

std::vector<NodeVector> apply_wall_contact(const CelGrid& grid,
                                           const std::vector<PlacedWall>& walls,
                                           const WallContactOptions& options, double dt,
                                           double void_node_mass, const CellFields& cells,
                                           NodeFields& nodes) {
  std::vector<NodeVector> reaction(walls.size(), NodeVector::Zero());
  if (walls.empty()) return reaction;
  const double d_c = options.contact_distance * grid.cell_size;
  std::vector<double> distance(walls.size());
  std::vector<NodeVector> normal(walls.size());
  for (std::size_t a = 0; a < grid.node_count(); ++a) {
    if (nodes.mass[a] <= void_node_mass) continue;
    const Eigen::Vector2d x = grid.node_position(a);
    std::size_t nearest = 0;
    for (std::size_t k = 0; k < walls.size(); ++k) {
      distance[k] = walls[k].signed_distance(x, &normal[k]);
      if (distance[k] < distance[nearest]) nearest = k;
    }
    const bool held = corner_of_wall_cell(grid, cells, a);
    for (std::size_t k = 0; k < walls.size(); ++k) {
      if (distance[k] >= d_c && !(held && k == nearest)) continue;
      const NodeVector& n = normal[k];
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
    // An empty cell whose centre is inside the walls, or all of whose corners are.
    bool inside = !walls.empty() && cells.mass[c] <= 0.0;
    if (inside && distance_to_walls(walls, grid.cell_centre(c)) > 0.0)
      for (std::size_t a : grid.cell_nodes(c)) {
        if (!inside) break;
        inside = distance_to_walls(walls, grid.node_position(a)) <= 0.0;
      }
    cells.solid[c] = inside ? kSolidInsideWall : 0;
  }
}

}  // namespace feedflow::cel
