#include "fullsim/cel/hopper_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "models/units/angle.hpp"

namespace feedflow::cel {
namespace {

constexpr double kRoundOffGap = 1e-9;  // of the cell size

// The same wall seen in the mirror x -> 2 centre - x; the points run the other way so the
// material stays on the left of travel.
RigidWall mirrored(RigidWall wall, double centre) {
  for (auto& p : wall.points) p.x() = 2.0 * centre - p.x();
  std::reverse(wall.points.begin(), wall.points.end());
  return wall;
}

// The wall moved away from the material by `gap` (each segment along its normal, kinks on the
// offset segments' intersections). Nodes on the walls' grid lines or at exactly the contact
// distance h/2 from a wall (the node above a 30 deg wall's outlet edge on a grid line) are
// otherwise decided by round-off, differently on the two walls of the full section; a gap far
// above round-off and far below anything physical decides them all as exact arithmetic does at
// the contact band (outside: d = h/2 is not < h/2) and at the kinks (the kink's normal).
RigidWall moved_off_material(RigidWall wall, double gap) {
  const auto& p = wall.points;
  std::vector<NodeVector> normal;  // per segment, into the material
  for (std::size_t s = 0; s + 1 < p.size(); ++s) {
    const NodeVector d = (p[s + 1] - p[s]).normalized();
    normal.emplace_back(-d.y(), d.x());
  }
  std::vector<Eigen::Vector2d> moved(p.size());
  moved.front() = p.front() - gap * normal.front();
  moved.back() = p.back() - gap * normal.back();
  for (std::size_t k = 1; k + 1 < p.size(); ++k)
    moved[k] = p[k] - gap * (normal[k - 1] + normal[k]) / (1.0 + normal[k - 1].dot(normal[k]));
  wall.points = moved;
  return wall;
}

}  // namespace

double hopper_centre_line(const Hopper& hopper, HopperSection section) {
  return section == HopperSection::full ? 0.5 * hopper.bin_width : 0.0;
}

const char* hopper_section_name(HopperSection section) {
  return section == HopperSection::full ? "full" : "half";
}

CelScene make_hopper_scene(const Hopper& hopper, double wall_friction_angle,
                           const SceneMaterial& material, double h, HopperSection section) {
  const bool cone = !hopper.is_wedge();
  if (cone && section == HopperSection::full)
    throw std::invalid_argument("a conical hopper is simulated axisymmetric about its axis; the "
                                "full-width section is for wedge hoppers");
  if (!(h > 0.0)) throw std::invalid_argument("cell size must be > 0");
  const bool full = section == HopperSection::full;
  const double t = std::tan(hopper.semi_angle);
  const double half_outlet = 0.5 * hopper.outlet_width, half_bin = 0.5 * hopper.bin_width;
  const double apex_depth = t > 0.0 ? half_outlet / t : 0.0;      // apex below the outlet plane
  const double knee = t > 0.0 ? (half_bin - half_outlet) / t : 0.0;  // top of the inclined wall
  const double top = hopper.fill_height - apex_depth;               // material top
  if (!(top > 0.0)) throw std::invalid_argument("the fill height is below the outlet");

  CelScene s;
  s.name = "hopper";
  // The half slice's columns, from the centre line to one cell beyond the bin wall; the full
  // section has them on both sides of the centre line xc.
  const int half_columns = static_cast<int>(std::ceil(half_bin / h)) + 1;
  const double xc = hopper_centre_line(hopper, section);
  const int rows = static_cast<int>(std::ceil(top / h)) + 2;
  s.grid = cone ? make_axisymmetric_grid(half_columns, rows, h)
                : make_plane_strain_grid(full ? 2 * half_columns : half_columns, rows, h,
                                         {full ? xc - half_columns * h : 0.0, 0.0});
  CelOptions& o = s.options;
  o.walls = {WallCondition::free_slip, WallCondition::free_slip, WallCondition::outflow,
             WallCondition::open};
  const double mu = std::tan(wall_friction_angle);
  const double y_top = s.grid.ny * h + 1.0;
  RigidWall wall;  // right-hand wall, travelled upward: the material is on its left
  wall.points = {{xc + half_outlet, -1.0}, {xc + half_outlet, 0.0}, {xc + half_bin, knee},
                 {xc + half_bin, y_top}};
  wall.friction = mu;
  wall = moved_off_material(wall, kRoundOffGap * h);
  o.rigid_walls = {wall};
  if (full) o.rigid_walls.push_back(mirrored(wall, xc));
  o.rigid_walls.push_back(make_half_plane_wall({xc, 0.0}, {0.0, 1.0}, mu));  // the gate
  const double x_left = full ? xc - half_bin : 0.0;
  s.material.push_back({{x_left, 0.0}, {xc + half_bin, top}, material.bulk_density,
                        material.void_ratio, -10.0 * Eigen::Matrix3d::Identity()});
  s.event = {"outlet gate removed", {o.rigid_walls.size() - 1}, {},
             std::numeric_limits<double>::infinity()};
  s.event_duration = 3.0;
  s.section_depth_factor = cone ? revolution_factor(s.grid) : full ? 1.0 : 2.0;
  char line[320];
  if (cone)
    std::snprintf(line, sizeof line,
                  "scene: conical hopper, axisymmetric (r, z) about its axis (the symmetry line, "
                  "free slip; per radian, x 2 pi), ");
  else if (full)
    std::snprintf(line, sizeof line,
                  "scene: wedge hopper, plane-strain full-width section (both walls, centre "
                  "line x = %.4g m), ", xc);
  else
    std::snprintf(line, sizeof line,
                  "scene: wedge hopper, plane-strain half slice (symmetry plane at the centre, "
                  "free slip), ");
  s.plan.push_back(line + grid_text(s.grid));
  std::snprintf(line, sizeof line,
                "walls: %s %.3g deg from the vertical from the outlet edge %s = %.4g m to "
                "the bin wall %s = %.4g m at %s = %.4g m, %s above%s; Coulomb mu = %.3f "
                "(%.3g deg)", cone ? "cone" : "inclined", in_degrees(hopper.semi_angle),
                cone ? "r" : "x", xc + half_outlet, cone ? "r" : "x", xc + half_bin,
                cone ? "z" : "y", knee, cone ? "cylinder" : "vertical",
                full ? ", and its mirror image about the centre line" : "", mu,
                in_degrees(wall_friction_angle));
  s.plan.push_back(line);
  std::snprintf(line, sizeof line,
                "fill: %.4g m above the outlet (%.4g m above the virtual apex), %.4g kg/m^3, "
                "e0 = %.4g, initial stress -10 Pa I", top, hopper.fill_height,
                material.bulk_density, material.void_ratio);
  s.plan.push_back(line);
  std::snprintf(line, sizeof line,
                "outlet: bottom box face from %s = %.4g m to %.4g m (outflow, mass booked), "
                "closed by a gate wall during the gravity phase; event: gate removed",
                cone ? "r" : "x", full ? xc - half_outlet : 0.0, xc + half_outlet);
  s.plan.push_back(line);
  s.plan.push_back(cone ? "skipped: flow off the axis' symmetry (swirl, asymmetric arches and "
                          "rat-holes), outlet inside the grid"
                   : full ? "skipped: outlet inside the grid (the outlet is the bottom box face)"
                          : "skipped: the other half (symmetry plane; [cel] hopper_section = "
                            "\"full\" simulates the full-width section), outlet inside the grid");
  return s;
}

}  // namespace feedflow::cel
