#include "fullsim/dem/wall.hpp"

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "models/core/errors.hpp"

namespace feedflow {

const char* to_string(WallContactSet set) {
  return set == WallContactSet::frictionless ? "frictionless" : "particle_wall";
}

Wall Wall::plane(std::string name, const Vec3& point, const Vec3& normal) {
  if (!(normal.norm() > 0.0)) throw InputError("", "wall." + name, "plane normal is zero");
  Wall w;
  w.shape_ = WallShape::plane;
  w.name_ = std::move(name);
  w.point_ = point;
  w.direction_ = normal.normalized();
  return w;
}

Wall Wall::cylinder(std::string name, const Vec3& point, const Vec3& axis, double radius,
                    bool particles_inside) {
  if (!(axis.norm() > 0.0) || !(radius > 0.0))
    throw InputError("", "wall." + name, "cylinder needs a non-zero axis and a positive radius");
  Wall w;
  w.shape_ = WallShape::cylinder;
  w.name_ = std::move(name);
  w.point_ = point;
  w.direction_ = axis.normalized();
  w.radius_ = radius;
  w.inside_ = particles_inside;
  return w;
}

Wall& Wall::moving(const Vec3& velocity, const Vec3& angular_velocity) {
  velocity_ = velocity;
  angular_velocity_ = angular_velocity;
  return *this;
}

Wall& Wall::removed_at(double t) {
  removal_time_ = t;
  return *this;
}

void Wall::advance(double dt) {
  point_ += dt * velocity_;
  const double turn = angular_velocity_.norm() * dt;
  if (turn > 0.0)
    direction_ = (Eigen::AngleAxisd(turn, angular_velocity_.normalized()) * direction_).normalized();
}

std::string wall_motion_text(const Vec3& velocity, const Vec3& angular_velocity, double removal_time) {
  std::string s;
  char buf[160];
  if (velocity.squaredNorm() > 0.0 || angular_velocity.squaredNorm() > 0.0) {
    std::snprintf(buf, sizeof buf, ", moving v = (%.3g, %.3g, %.3g) m/s, omega = (%.3g, %.3g, %.3g) rad/s",
                  velocity.x(), velocity.y(), velocity.z(), angular_velocity.x(), angular_velocity.y(),
                  angular_velocity.z());
    s += buf;
  }
  if (std::isfinite(removal_time)) {
    std::snprintf(buf, sizeof buf, ", removed at t = %.4g s", removal_time);
    s += buf;
  }
  return s;
}

std::string Wall::describe() const {
  char buf[256];
  if (shape_ == WallShape::plane)
    std::snprintf(buf, sizeof buf, "plane '%s' through (%.4g, %.4g, %.4g) normal (%.3g, %.3g, %.3g)",
                  name_.c_str(), point_.x(), point_.y(), point_.z(), direction_.x(),
                  direction_.y(), direction_.z());
  else
    std::snprintf(buf, sizeof buf, "cylinder '%s' R = %.4g m, axis (%.3g, %.3g, %.3g), particles %s",
                  name_.c_str(), radius_, direction_.x(), direction_.y(), direction_.z(),
                  inside_ ? "inside" : "outside");
  std::string s = buf;
  if (contact_set_ == WallContactSet::frictionless)
    s += ", frictionless (P-W normal law and damping, no sliding or rolling resistance)";
  return s + wall_motion_text(velocity_, angular_velocity_, removal_time_);
}

}  // namespace feedflow
