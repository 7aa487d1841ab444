#include "fullsim/cel/rigid_wall.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace feedflow::cel {

RigidWall make_half_plane_wall(const Eigen::Vector2d& point, const NodeVector& normal,
                               double friction) {
  const NodeVector n = normal.normalized();
  const NodeVector along(n.y(), -n.x());  // travel direction with n on its left
  RigidWall w;
  w.points = {point - along, point + along};
  w.friction = friction;
  return w;
}

double RigidWall::motion_time(double t) const {
  return std::max(0.0, std::min(t, motion_end) - motion_start);
}

PlacedWall::PlacedWall(const RigidWall& wall, double t) : wall_(&wall), moving_(wall.moving(t)) {
  if (wall.points.size() < (wall.closed ? 3u : 2u))
    throw std::invalid_argument("a rigid wall needs at least two points (three when closed)");
  const double tm = wall.motion_time(t);
  const Eigen::Rotation2Dd turn(wall.angular_velocity * tm);
  centre_ = wall.centre + tm * wall.velocity;
  points_.reserve(wall.points.size() + 1);
  for (const auto& p : wall.points) points_.push_back(centre_ + turn * (p - wall.centre));
  if (wall.closed) points_.push_back(points_.front());
  for (std::size_t s = 0; s + 1 < points_.size(); ++s) {
    const NodeVector d = points_[s + 1] - points_[s];
    const double len = d.norm();
    if (len <= 0.0) throw std::invalid_argument("a rigid wall has a segment of zero length");
    normals_.emplace_back(-d.y() / len, d.x() / len);
  }
}

double PlacedWall::signed_distance(const Eigen::Vector2d& x, NodeVector* normal) const {
  const std::size_t segments = normals_.size();
  double best = std::numeric_limits<double>::infinity();
  double sign = 1.0;
  NodeVector best_normal = normals_[0];
  for (std::size_t s = 0; s < segments; ++s) {
    const Eigen::Vector2d a = points_[s];
    const NodeVector d = points_[s + 1] - a;
    double u = (x - a).dot(d) / d.squaredNorm();
    // End segments continue as rays; an interior end is a kink shared with the neighbour (on a
    // closed wall every end is).
    const bool closed = wall_->closed;
    const bool kink_lo = (closed || s > 0) && u <= 0.0;
    const bool kink_hi = (closed || s + 1 < segments) && u >= 1.0;
    if (kink_lo) u = 0.0;
    if (kink_hi) u = 1.0;
    const Eigen::Vector2d p = a + u * d;
    const double dist = (x - p).norm();
    if (dist >= best) continue;
    best = dist;
    NodeVector n = normals_[s];
    const std::size_t before = s > 0 ? s - 1 : segments - 1, after = s + 1 < segments ? s + 1 : 0;
    if (kink_lo) n = (normals_[before] + normals_[s]).normalized();
    if (kink_hi) n = (normals_[s] + normals_[after]).normalized();
    best_normal = n;
    sign = (x - p).dot(n) < 0.0 ? -1.0 : 1.0;
  }
  if (normal) *normal = best_normal;
  return sign * best;
}

NodeVector PlacedWall::velocity_at(const Eigen::Vector2d& x) const {
  if (!moving_) return NodeVector::Zero();
  const NodeVector r = x - centre_;
  return wall_->velocity + wall_->angular_velocity * NodeVector(-r.y(), r.x());
}

}  // namespace feedflow::cel
