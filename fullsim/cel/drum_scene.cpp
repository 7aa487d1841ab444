#include "fullsim/cel/drum_scene.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "models/units/angle.hpp"

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

FreeSurface drum_surface(const CelSolver& solver, const DrumSection& section, double span) {
  const CelGrid& g = solver.grid();
  const double t = solver.time();
  const NodeVector down = solver.frame().gravity(solver.options().gravity, t).normalized();
  const NodeVector up = -down, across(up.y(), -up.x());  // (across, up) right-handed
  const auto filled = [&](const Eigen::Vector2d& x) {
    const Eigen::Vector2d q = (x - g.origin) / g.cell_size;
    const int i = static_cast<int>(std::floor(q.x())), j = static_cast<int>(std::floor(q.y()));
    if (i < 0 || j < 0 || i >= g.nx || j >= g.ny) return false;
    return solver.cells().volume_fraction[g.cell(i, j)] >= 0.5;
  };
  FreeSurface f;
  const double step = 0.25 * g.cell_size, r = section.radius;
  for (double s = -span * r; s <= span * r; s += 0.5 * g.cell_size) {
    // Up from the shell's lowest point on this line: the first filled point, then the first
    // empty one above it (material thrown above the bed is ignored).
    const double depth = std::sqrt(std::max(0.0, r * r - s * s));
    bool in_bed = false;
    for (double u = -depth; u <= depth; u += step) {
      const bool full = filled(section.centre + s * across + u * up);
      if (!in_bed && full) in_bed = true;
      if (in_bed && !full) {
        f.x.push_back(s);
        f.y.push_back(u - 0.5 * step);
        break;
      }
    }
  }
  f.slope_angle = fitted_slope_angle(f.x, f.y);
  return f;
}

CelScene make_drum_scene(const Drum& drum, double wall_friction_angle,
                         const SceneMaterial& material, double h, DrumFrame frame) {
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
  const bool in_shell_frame = frame == DrumFrame::shell;
  if (in_shell_frame) {  // the shell rests on the grid: the solver turns with it from the event on
    o.frame.centre = d.centre;
    o.frame.angular_velocity = drum.speed;
  } else {
    shell.centre = d.centre;
    shell.angular_velocity = drum.speed;
    shell.motion_start = std::numeric_limits<double>::infinity();  // set by the event
  }
  o.rigid_walls = {shell};
  // The turning bed's surface needs a sharp interface: with the donor cell it smears through
  // the whole bed in either frame (170 of 174 cells mixed after 4 s at 10 mm cells).
  o.remap.material_flux = MaterialFlux::plic;
  const double level = d.centre.y() - d.radius + fill_level(d.radius, drum.fill_fraction);
  s.material.push_back({{0.0, 0.0}, {n * h, level}, material.bulk_density, material.void_ratio,
                        -10.0 * Eigen::Matrix3d::Identity()});
  s.event = {"drum started", {}, {}, std::numeric_limits<double>::infinity(), in_shell_frame};
  if (!in_shell_frame) s.event.walls_started = {0};
  // The seed's 10 s of rotation: the first avalanche's overshoot decays over about a turn (6 s
  // at 10 rpm), then the surface swings with a period near 1 s.
  s.event_duration = 10.0;
  char line[480];
  s.plan.push_back("scene: rotating drum, plane-strain section, " + grid_text(s.grid));
  std::snprintf(line, sizeof line,
                "shell: circle D = %.4g m (%d segments), Coulomb mu = %.3f (%.3g deg), "
                "counter-clockwise at %.4g rpm from the event, %s", drum.diameter, segments,
                shell.friction, in_degrees(wall_friction_angle), in_rpm(drum.speed),
                in_shell_frame ? "solved in the shell's turning frame (gravity turns, "
                                 "centrifugal and Coriolis forces on the nodes; velocities "
                                 "relative to the shell)"
                               : "solved in the laboratory frame (the shell turns on the grid)");
  s.plan.push_back(line);
  std::snprintf(line, sizeof line, "fill: %.3g %% of the section (level %.4g m above the lowest "
                "point), %.4g kg/m^3, e0 = %.4g; cut cells fill whole (a little extra mass)",
                drum.fill_fraction * 100.0, level - (d.centre.y() - d.radius),
                material.bulk_density, material.void_ratio);
  s.plan.push_back(line);
  s.plan.push_back("material flux: PLIC unless the case names another ([cel] material_flux)");
  s.plan.push_back("skipped: end walls (plane strain)");
  return s;
}

}  // namespace feedflow::cel
