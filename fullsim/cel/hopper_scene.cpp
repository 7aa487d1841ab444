#include "fullsim/cel/hopper_scene.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace feedflow::cel {

CelScene make_hopper_scene(const Hopper& hopper, double wall_friction_angle,
                           const SceneMaterial& material, double h) {
  if (!hopper.is_wedge())
    throw std::invalid_argument("the CEL hopper scene is plane strain: wedge hoppers only");
  if (!(h > 0.0)) throw std::invalid_argument("cell size must be > 0");
  const double t = std::tan(hopper.semi_angle);
  const double half_outlet = 0.5 * hopper.outlet_width, half_bin = 0.5 * hopper.bin_width;
  const double apex_depth = t > 0.0 ? half_outlet / t : 0.0;      // apex below the outlet plane
  const double knee = t > 0.0 ? (half_bin - half_outlet) / t : 0.0;  // top of the inclined wall
  const double top = hopper.fill_height - apex_depth;               // material top
  if (!(top > 0.0)) throw std::invalid_argument("the fill height is below the outlet");

  CelScene s;
  s.name = "hopper";
  s.grid = make_plane_strain_grid(static_cast<int>(std::ceil(half_bin / h)) + 1,
                                  static_cast<int>(std::ceil(top / h)) + 2, h);
  CelOptions& o = s.options;
  o.walls = {WallCondition::free_slip, WallCondition::free_slip, WallCondition::outflow,
             WallCondition::open};
  const double mu = std::tan(wall_friction_angle);
  const double y_top = s.grid.ny * h + 1.0;
  RigidWall wall;
  wall.points = {{half_outlet, -1.0}, {half_outlet, 0.0}, {half_bin, knee}, {half_bin, y_top}};
  wall.friction = mu;
  RigidWall gate = make_half_plane_wall({0.0, 0.0}, {0.0, 1.0}, mu);
  o.rigid_walls = {wall, gate};
  s.material.push_back({{0.0, 0.0}, {half_bin, top}, material.bulk_density, material.void_ratio,
                        -10.0 * Eigen::Matrix3d::Identity()});
  s.event = {"outlet gate removed", {1}, {}, std::numeric_limits<double>::infinity()};
  s.event_duration = 3.0;
  s.section_depth_factor = 2.0;
  char line[240];
  s.plan.push_back("scene: wedge hopper, plane-strain half slice (symmetry plane at the centre, "
                   "free slip), " + grid_text(s.grid));
  std::snprintf(line, sizeof line,
                "walls: inclined %.3g deg from the vertical from the outlet edge x = %.4g m to "
                "the bin wall x = %.4g m at y = %.4g m, vertical above; Coulomb mu = %.3f "
                "(%.3g deg)", hopper.semi_angle * 180.0 / M_PI, half_outlet, half_bin, knee, mu,
                wall_friction_angle * 180.0 / M_PI);
  s.plan.push_back(line);
  std::snprintf(line, sizeof line,
                "fill: %.4g m above the outlet (%.4g m above the virtual apex), %.4g kg/m^3, "
                "e0 = %.4g, initial stress -10 Pa I", top, hopper.fill_height,
                material.bulk_density, material.void_ratio);
  s.plan.push_back(line);
  s.plan.push_back("outlet: bottom box face (outflow, mass booked), closed by a gate wall "
                   "during the gravity phase; event: gate removed");
  s.plan.push_back("skipped: full-width "
                   "section (half slice), outlet inside the grid");
  return s;
}

}  // namespace feedflow::cel
