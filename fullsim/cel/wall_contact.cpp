#include "fullsim/cel/wall_contact.hpp"

#include <algorithm>
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

// A wall a node touches: its index, unit normal (into the material) and velocity at the node.
struct Touch {
  std::size_t index;
  const RigidWall* wall;
  NodeVector n;
  NodeVector vw;
};

// Whether v moves into none of the touched walls (to round-off).
bool admissible(const NodeVector& v, const std::vector<Touch>& touches) {
  for (const auto& t : touches) {
    const NodeVector rel = v - t.vw;
    if (rel.dot(t.n) < -1e-12 * (v.norm() + t.vw.norm())) return false;
  }
  return true;
}

// The velocity a node moving at v takes against the walls it touches, and in `impulse` what each
// gave per unit mass. Its frictionless part is the
// nearest velocity that moves into none of them (a convex projection: the nearest of the
// candidates with one or two active walls, two independent normals fixing a velocity in 2D, whose
// impulses push); Coulomb friction then acts when one wall is active. Projecting on the walls one
// after another instead turns a node pressed into a corner (a wedge's outlet lip on its closed
// gate) into one sliding along the second wall: at low wall friction the lip slid on the gate,
// emptied its cell and crushed what was left.
NodeVector meet_walls(const NodeVector& v, const std::vector<Touch>& touches,
                      std::vector<NodeVector>& impulse) {
  impulse.assign(touches.size(), NodeVector::Zero());
  if (admissible(v, touches)) return v;
  NodeVector velocity = v;
  double nearest = std::numeric_limits<double>::infinity();
  const std::size_t none = touches.size();
  std::size_t single = none;  // the one active wall of the nearest candidate, if one
  for (std::size_t k = 0; k < touches.size(); ++k) {
    const double vn = (v - touches[k].vw).dot(touches[k].n);
    if (vn < 0.0 && -vn < nearest && admissible(v - vn * touches[k].n, touches)) {
      nearest = -vn;
      single = k;
    }
  }
  for (std::size_t k = 0; k < touches.size(); ++k)
    for (std::size_t l = k + 1; l < touches.size(); ++l) {
      // Cramer's rule, so that a corner of resting walls stops the node exactly.
      const NodeVector &nk = touches[k].n, &nl = touches[l].n;
      const double det = nk.x() * nl.y() - nk.y() * nl.x();
      if (std::abs(det) < 1e-6) continue;  // (anti)parallel walls
      const double tk = touches[k].vw.dot(nk), tl = touches[l].vw.dot(nl);
      const NodeVector stuck((tk * nl.y() - nk.y() * tl) / det, (nk.x() * tl - tk * nl.x()) / det);
      const NodeVector d = stuck - v;
      const double lk = (d.x() * nl.y() - nl.x() * d.y()) / det,
                   ll = (nk.x() * d.y() - d.x() * nk.y()) / det;
      if (lk < 0.0 || ll < 0.0 || d.norm() >= nearest || !admissible(stuck, touches)) continue;
      nearest = d.norm();
      single = none;
      std::fill(impulse.begin(), impulse.end(), NodeVector::Zero());
      impulse[k] = lk * nk;
      impulse[l] = ll * nl;
      velocity = stuck;
    }
  if (single != none) {
    const Touch& t = touches[single];
    velocity = t.vw + project(v - t.vw, t.n, *t.wall);
    impulse[single] = velocity - v;
    return velocity;
  }
  if (std::isfinite(nearest)) return velocity;
  // No consistent active set (walls squeezing the node from opposite sides): one after another.
  for (std::size_t k = 0; k < touches.size(); ++k) {
    const NodeVector before = velocity;
    velocity = touches[k].vw + project(before - touches[k].vw, touches[k].n, *touches[k].wall);
    impulse[k] = velocity - before;
  }
  return velocity;
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
  std::vector<Touch> touches;
  std::vector<NodeVector> impulse;
  for (std::size_t a = 0; a < grid.node_count(); ++a) {
    if (nodes.mass[a] <= void_node_mass) continue;
    const Eigen::Vector2d x = grid.node_position(a);
    std::size_t nearest = 0;
    for (std::size_t k = 0; k < walls.size(); ++k) {
      distance[k] = walls[k].signed_distance(x, &normal[k]);
      if (distance[k] < distance[nearest]) nearest = k;
    }
    const bool held = corner_of_wall_cell(grid, cells, a);
    touches.clear();
    for (std::size_t k = 0; k < walls.size(); ++k)
      if (distance[k] < d_c || (held && k == nearest))
        touches.push_back({k, &walls[k].wall(), normal[k], walls[k].velocity_at(x)});
    if (touches.empty()) continue;
    nodes.velocity[a] = meet_walls(nodes.velocity[a], touches, impulse);
    for (std::size_t t = 0; t < touches.size(); ++t)
      reaction[touches[t].index] += nodes.mass[a] * impulse[t] / dt;
  }
  return reaction;
}

void mark_wall_cells(const CelGrid& grid, const std::vector<PlacedWall>& walls,
                     CellFields& cells) {
  // A centre on a wall's face is outside: half of its cell is open, and the cell must carry
  // flux along the face. (Marked, the empty cells along a chute gate whose face ran through
  // their centres walled in the full one between them: its nodes fell along the gate without
  // end, and the run blew up at 50 m/s.)
  const double on_face = 1e-9 * grid.cell_size;
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    if (cells.solid[c] == kSolidFixed) continue;
    // An empty cell whose centre is inside the walls, or all of whose corners are.
    bool inside = !walls.empty() && cells.mass[c] <= 0.0;
    if (inside && distance_to_walls(walls, grid.cell_centre(c)) > -on_face)
      for (std::size_t a : grid.cell_nodes(c)) {
        if (!inside) break;
        inside = distance_to_walls(walls, grid.node_position(a)) <= 0.0;
      }
    cells.solid[c] = inside ? kSolidInsideWall : 0;
  }
}

}  // namespace feedflow::cel
