#include "fullsim/cel/drum_scene.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace feedflow::cel {

DrumSection drum_section(const Drum& drum, double h) {
  const double r = 0.5 * drum.diameter;
  return {Eigen::Vector2d(r + 2.0 * h, r + 2.0 * h), r};
}

double fill_level(double r, double f) {
  double lo = 0.0, hi = 2.0 * r;
  for (int k = 0; k < 60; ++k) {  // segment area r^2 (a - sin a)/2 with a = 2 acos(1 - y/r)
    const double y = 0.5 * (lo + hi);
    const double a = 2.0 * std::acos(1.0 - y / r);
    const double share = (a - std::sin(a)) / (2.0 * std::numbers::pi);
    (share < f ? lo : hi) = y;
  }
  return 0.5 * (lo + hi);
}

CelScene make_drum_scene(const Drum& drum, double wall_friction_angle,
                         const SceneMaterial& material, double h) {
  if (!(h > 0.0)) throw std::invalid_argument("cell size must be > 0");
  const DrumSection d = drum_section(drum, h);
  CelScene s;
  s.name = "drum";
  const int n = static_cast<int>(std::ceil((2.0 * d.radius + 4.0 * h) / h));
  s.grid = make_plane_strain_grid(n, n, h);
  CelOptions& o = s.options;
  o.walls = {WallCondition::free_slip, WallCondition::free_slip, WallCondition::free_slip,
             WallCondition::free_slip};
  RigidWall shell;
  const int segments =
      std::max(64, static_cast<int>(std::ceil(2.0 * std::numbers::pi * d.radius / (0.5 * h))));
  for (int k = 0; k < segments; ++k) {
    const double a = 2.0 * std::numbers::pi * k / segments;
    shell.points.push_back(d.centre + d.radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  shell.closed = true;
  shell.friction = std::tan(wall_friction_angle);
  shell.centre = d.centre;
  shell.angular_velocity = drum.speed;
  shell.motion_start = std::numeric_limits<double>::infinity();  // set by the event
  o.rigid_walls = {shell};
  const double level = d.centre.y() - d.radius + fill_level(d.radius, drum.fill_fraction);
  s.material.push_back({{0.0, 0.0}, {n * h, level}, material.bulk_density, material.void_ratio,
                        -10.0 * Eigen::Matrix3d::Identity()});
  s.event = {"drum started", {}, {0}, std::numeric_limits<double>::infinity()};
  s.event_duration = 4.0;
  char line[240];
  s.plan.push_back("scene: rotating drum, plane-strain section, " + grid_text(s.grid));
  std::snprintf(line, sizeof line,
                "shell: circle D = %.4g m (%d segments), Coulomb mu = %.3f (%.3g deg), "
                "counter-clockwise at %.4g rpm from the event", drum.diameter, segments,
                shell.friction, wall_friction_angle * 180.0 / std::numbers::pi,
                drum.speed * 60.0 / (2.0 * std::numbers::pi));
  s.plan.push_back(line);
  std::snprintf(line, sizeof line, "fill: %.3g %% of the section (level %.4g m above the lowest "
                "point), %.4g kg/m^3, e0 = %.4g; cut cells fill whole (a little extra mass)",
                drum.fill_fraction * 100.0, level - (d.centre.y() - d.radius),
                material.bulk_density, material.void_ratio);
  s.plan.push_back(line);
  s.plan.push_back("skipped: end walls (plane strain)");
  return s;
}

}  // namespace feedflow::cel
