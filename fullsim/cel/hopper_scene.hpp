#pragma once
// The CEL scene of a wedge hopper (seed FEM deck, data.md 2.1-2.2): a plane-strain half slice
// with the symmetry plane at x = 0 (free-slip left face), the inclined wall from the outlet edge
// (W/2, 0) to the bin wall, the vertical bin wall above, Coulomb friction at the wall friction
// angle, the outlet on the bottom box face (outflow: the mass leaving is booked) closed by a gate
// wall during the gravity phase and removed at the event. Material fills the section to the
// fill height above the virtual apex.
#include "fullsim/cel/cel_scene.hpp"
#include "models/equipment/hopper.hpp"

namespace feedflow::cel {

// Throws std::invalid_argument for a conical hopper (plane strain only) or h <= 0.
CelScene make_hopper_scene(const Hopper& hopper, double wall_friction_angle,
                           const SceneMaterial& material, double cell_size);

}  // namespace feedflow::cel
