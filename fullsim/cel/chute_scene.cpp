#include "fullsim/cel/chute_scene.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "models/units/angle.hpp"

namespace feedflow::cel {

CelScene make_chute_scene(const Chute& chute, const SceneMaterial& material, double h) {
  if (!(h > 0.0)) throw std::invalid_argument("cell size must be > 0");
  CelScene s;
  s.name = "chute";
  const double x_gate = chute.bin_length, thickness = 2.0 * h;
  const double height = std::max(chute.fill_height, chute.gate_opening) + 2.0 * h;
  s.grid = make_plane_strain_grid(
      static_cast<int>(std::ceil((chute.bin_length + thickness + chute.length) / h)),
      static_cast<int>(std::ceil(height / h)), h);
  CelOptions& o = s.options;
  o.walls = {WallCondition::free_slip, WallCondition::outflow, WallCondition::no_slip,
             WallCondition::open};
  o.gravity = 9.81 * NodeVector(std::sin(chute.angle), -std::cos(chute.angle));
  const double y_top = s.grid.ny * h + 1.0;
  RigidWall gate;  // a plate from the ramp up, open at the top; material on both sides
  gate.points = {{x_gate + thickness, y_top}, {x_gate + thickness, 0.0}, {x_gate, 0.0},
                 {x_gate, y_top}};
  gate.velocity = NodeVector(0.0, kGateLiftSpeed);
  gate.motion_start = std::numeric_limits<double>::infinity();  // set by the event
  o.rigid_walls = {gate};
  // The deposit is a layer with a free surface: with the donor cell it smears into a half-full
  // cloud several cells deep (largest volume fraction mid-ramp 0.37 / 0.69 / 0.77 on 20 / 10 /
  // 5 mm cells); PLIC keeps it full with one mixed cell on top.
  o.remap.material_flux = MaterialFlux::plic;
  s.material.push_back({{0.0, 0.0}, {chute.bin_length, chute.fill_height}, material.bulk_density,
                        material.void_ratio, -10.0 * Eigen::Matrix3d::Identity()});
  s.event = {"gate lifted", {}, {0}, chute.gate_opening / kGateLiftSpeed};
  s.event_duration = 6.0;
  char line[260];
  s.plan.push_back("scene: inclined plane, plane-strain slice in the ramp frame, " +
                   grid_text(s.grid));
  std::snprintf(line, sizeof line,
                "ramp: %.3g deg, no slip, %.4g m long after the gate; bin %.4g m long on the "
                "ramp (free-slip back wall, bin floor on the ramp), fill %.4g m, %.4g kg/m^3, "
                "e0 = %.4g", in_degrees(chute.angle), chute.length,
                chute.bin_length, chute.fill_height, material.bulk_density, material.void_ratio);
  s.plan.push_back(line);
  std::snprintf(line, sizeof line,
                "gate: free-slip plate normal to the ramp, lifted at %.3g m/s to %.4g m at the "
                "event; the end of the ramp is an outflow face (run-off booked)",
                kGateLiftSpeed, chute.gate_opening);
  s.plan.push_back(line);
  s.plan.push_back("material flux: PLIC unless the case names another ([cel] material_flux)");
  s.plan.push_back("skipped: ramp side walls and lateral spill (plane strain), vertical bin "
                   "walls (normal to the ramp here)");
  return s;
}

}  // namespace feedflow::cel
