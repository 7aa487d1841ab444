#include "fullsim/cel/turning_frame.hpp"

#include <cmath>

namespace feedflow::cel {
namespace {

NodeVector turned(const NodeVector& v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

NodeVector TurningFrame::gravity(const NodeVector& g, double t) const { return turned(g, -angle(t)); }

NodeVector TurningFrame::to_lab(const NodeVector& v, double t) const { return turned(v, angle(t)); }

NodeVector TurningFrame::carried_velocity(const Eigen::Vector2d& x) const {
  const Eigen::Vector2d r = x - centre;
  return angular_velocity * NodeVector(-r.y(), r.x());
}

void add_frame_forces(const TurningFrame& frame, const CelGrid& grid, double t,
                      double void_node_mass, NodeFields& nodes) {
  if (!frame.turning(t)) return;
  const double w = frame.angular_velocity;
  for (std::size_t a = 0; a < grid.node_count(); ++a) {
    const double m = nodes.mass[a];
    if (m <= void_node_mass) continue;
    const Eigen::Vector2d r = grid.node_position(a) - frame.centre;
    const NodeVector& v = nodes.velocity[a];
    // -omega x (omega x r) = omega^2 r; -2 omega x v = 2 omega (v_y, -v_x).
    nodes.force[a] += m * (w * w * NodeVector(r.x(), r.y()) + 2.0 * w * NodeVector(v.y(), -v.x()));
  }
}

}  // namespace feedflow::cel
