#pragma once
// The CEL scene of a rotating drum (seed FEM, data.md 4): a plane-strain section, the drum
// shell a closed polygon wall (segments of at most h/2) with Coulomb friction at the wall
// friction angle, at rest during the gravity phase and turning counter-clockwise at the case's
// speed from the event on; material filled to the fill fraction of the cross-section. The turn
// is solved in the shell's frame (turning_frame.hpp): the shell stays on the grid and gravity
// turns, so the bed that turns with the shell is not advected through the grid (in the
// laboratory frame the donor cell smeared the whole bed within 1.2 s, and PLIC left material in
// cut cells at the moving shell whose nodes then slid without end).
//
// `drum_surface`: the bed's free surface (volume fraction 0.5) across the current gravity
// direction, over |s| <= span x R about the centre, its slope against the laboratory
// horizontal.
#include "fullsim/cel/cel_scene.hpp"
#include "fullsim/cel/scene_measurements.hpp"
#include "models/equipment/drum.hpp"

namespace feedflow::cel {

struct DrumSection {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // [m]
  double radius = 0.0;                               // [m]
};

DrumSection drum_section(const Drum& drum, double cell_size);

// Height above the lowest point of a circle of radius r at which the segment below holds the
// fraction f of its area [m].
double fill_level(double radius, double fraction);

// The points are (across, up) the current gravity direction from the centre [m].
FreeSurface drum_surface(const CelSolver& solver, const DrumSection& section, double span);

// The frame the turn is solved in: the shell's (default) or the laboratory's (the shell turns
// on the grid; kept for the wall-contact tests and for comparison).
enum class DrumFrame { shell, laboratory };

CelScene make_drum_scene(const Drum& drum, double wall_friction_angle,
                         const SceneMaterial& material, double cell_size,
                         DrumFrame frame = DrumFrame::shell);

}  // namespace feedflow::cel
