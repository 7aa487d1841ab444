#pragma once
// A rigid wall of the plane-strain section described by a signed distance (models.md 2.6, option
// C1): a polyline whose two end segments are extended to rays, so it divides the plane into the
// material side (left of the direction of travel along the points, where the distance is
// positive) and the wall solid (negative). One segment is a half-plane at any angle; three points
// make a hopper wall with a kink. A closed polyline (a drum shell) has no rays: material inside
// when its points run counter-clockwise. The wall may move rigidly (translation plus rotation
// about a centre, for the drum) during a motion interval (a gate lifted to its opening, a drum
// started after the gravity phase) and may be removed at a time (a gate over a hopper outlet).
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "fullsim/cel/cel_grid.hpp"

namespace feedflow::cel {

struct RigidWall {
  std::vector<Eigen::Vector2d> points;  // at t = 0, >= 2; material on the left of travel [m]
  double friction = 0.0;                // Coulomb coefficient mu (tan 8.5 deg: pine on steel)
  bool no_slip = false;                 // stick whenever in contact (mu -> infinity)
  NodeVector velocity = NodeVector::Zero();         // translation [m/s]
  double angular_velocity = 0.0;                    // counter-clockwise about `centre` [rad/s]
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // rotation centre at t = 0 [m]
  double removal_time = std::numeric_limits<double>::infinity();  // gone for t >= this [s]
  bool closed = false;       // the last point joins the first (no end rays)
  double motion_start = 0.0;  // the wall moves with `velocity`/`angular_velocity` from here [s]
  double motion_end = std::numeric_limits<double>::infinity();  // and rests again from here [s]

  bool present(double t) const { return t < removal_time; }
  bool moving(double t) const { return t >= motion_start && t < motion_end; }
  // Time spent moving up to t [s].
  double motion_time(double t) const;
};

// A half-plane wall through `point` whose outward normal (into the material) is `normal`.
RigidWall make_half_plane_wall(const Eigen::Vector2d& point, const NodeVector& normal,
                               double friction = 0.0);

// The wall at one time: placed points, unit segment normals, and its rigid motion.
class PlacedWall {
 public:
  PlacedWall(const RigidWall& wall, double t);

  // Signed distance of x (positive on the material side) and the unit normal of the nearest
  // feature (into the material; at a kink the mean of the two segment normals).
  double signed_distance(const Eigen::Vector2d& x, NodeVector* normal = nullptr) const;
  // Velocity of the wall's material point at x [m/s].
  NodeVector velocity_at(const Eigen::Vector2d& x) const;
  const RigidWall& wall() const { return *wall_; }
  // The placed points (a closed wall repeats its first point at the end).
  const std::vector<Eigen::Vector2d>& points() const { return points_; }

 private:
  const RigidWall* wall_;
  std::vector<Eigen::Vector2d> points_;
  std::vector<NodeVector> normals_;  // per segment
  Eigen::Vector2d centre_;
  bool moving_ = false;
};

}  // namespace feedflow::cel
