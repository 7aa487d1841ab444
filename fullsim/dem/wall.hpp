#pragma once
// Analytic walls: an infinite plane (particles on the side its normal points to) and a
// cylinder (particles inside or outside). A wall may move rigidly with a linear velocity and
// an angular velocity about a centre (a drum turns about its axis), and may be removed at a
// given time (a gate lifted). Its contacts use the particle-wall parameter set, or that set
// without sliding and rolling resistance (a frictionless face: the normal law and its damping
// as P-W, no tangential force, no rolling torque).
#include <cmath>
#include <limits>
#include <string>

#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

enum class WallShape { plane, cylinder };

// The contact parameters of a wall: the particle-wall Table 2 set, or the same set with zero
// sliding and rolling friction (a frictionless face).
enum class WallContactSet { particle_wall, frictionless };
const char* to_string(WallContactSet set);

// Where a sphere touches a wall.
struct WallTouch {
  double gap = 0.0;               // distance of the centre to the surface along the normal [m]
  Vec3 normal = Vec3::UnitZ();    // unit normal from the wall towards the particle
};

class Wall {
 public:
  // Plane through `point` with `normal` pointing to the particle side.
  static Wall plane(std::string name, const Vec3& point, const Vec3& normal);
  // Cylinder of `radius` around the axis through `point` along `axis`; particles inside it
  // (a drum, a pipe) or outside it (a rod).
  static Wall cylinder(std::string name, const Vec3& point, const Vec3& axis, double radius,
                       bool particles_inside);

  // Rigid motion: the wall's point moves with `velocity`; it turns with `angular_velocity`
  // about its point (for a cylinder: about its axis when parallel to it).
  Wall& moving(const Vec3& velocity, const Vec3& angular_velocity);
  // The wall is gone from time `t` on.
  Wall& removed_at(double t);
  // Its contacts take `set` (default: the particle-wall set).
  Wall& with_contact_set(WallContactSet set) {
    contact_set_ = set;
    return *this;
  }
  // Sets the current point and direction as they are (restoring a checkpoint: no
  // normalisation, so a restarted run sees the same bits).
  Wall& placed(const Vec3& point, const Vec3& direction) {
    point_ = point;
    direction_ = direction;
    return *this;
  }

  WallShape shape() const { return shape_; }
  const std::string& name() const { return name_; }
  const Vec3& point() const { return point_; }
  const Vec3& direction() const { return direction_; }  // plane normal or cylinder axis
  double radius() const { return radius_; }
  bool particles_inside() const { return inside_; }
  const Vec3& velocity() const { return velocity_; }
  const Vec3& angular_velocity() const { return angular_velocity_; }
  bool moves() const { return velocity_.squaredNorm() > 0.0 || angular_velocity_.squaredNorm() > 0.0; }
  bool active(double t) const { return t < removal_time_; }
  double removal_time() const { return removal_time_; }
  WallContactSet contact_set() const { return contact_set_; }
  std::string describe() const;

  // Advances the rigid motion by dt.
  void advance(double dt);

  // The contact of a sphere centred at x (gap < radius means overlap).
  WallTouch touch(const Vec3& x) const {
    WallTouch t;
    if (shape_ == WallShape::plane) {
      t.gap = dot(x - point_, direction_);  // models/contact/contact_kinematics.hpp
      t.normal = direction_;
    } else {
      const Vec3 rel = x - point_;
      const Vec3 radial = rel - dot(rel, direction_) * direction_;
      const double r = std::sqrt(squared_norm(radial));
      const Vec3 out = r > 0.0 ? Vec3(radial / r) : Vec3(direction_.unitOrthogonal());
      t.gap = inside_ ? radius_ - r : r - radius_;
      t.normal = inside_ ? Vec3(-out) : out;
    }
    return t;
  }
  // The velocity of the wall's surface at a point of it [m/s].
  Vec3 surface_velocity(const Vec3& contact) const {
    return velocity_ + angular_velocity_.cross(contact - point_);
  }

 private:
  WallShape shape_ = WallShape::plane;
  std::string name_;
  Vec3 point_ = Vec3::Zero();
  Vec3 direction_ = Vec3::UnitZ();
  double radius_ = 0.0;
  bool inside_ = true;
  Vec3 velocity_ = Vec3::Zero();
  Vec3 angular_velocity_ = Vec3::Zero();
  double removal_time_ = std::numeric_limits<double>::infinity();
  WallContactSet contact_set_ = WallContactSet::particle_wall;
};

// ", moving v = (...) m/s, omega = (...) rad/s, removed at t = ... s" for a wall's plan line;
// empty for a wall that stays put for the whole run.
std::string wall_motion_text(const Vec3& velocity, const Vec3& angular_velocity, double removal_time);

}  // namespace feedflow
