#pragma once
// The CEL scene of a rotating drum (seed FEM, data.md 4): a plane-strain section, the drum
// shell a closed polygon wall (segments of at most h/2) with Coulomb friction at the wall
// friction angle, at rest during the gravity phase and turning counter-clockwise at the case's
// speed from the event on; material filled to the fill fraction of the cross-section.
#include "fullsim/cel/cel_scene.hpp"
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

CelScene make_drum_scene(const Drum& drum, double wall_friction_angle,
                         const SceneMaterial& material, double cell_size);

}  // namespace feedflow::cel
