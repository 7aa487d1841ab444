#pragma once
// The CEL scene of the inclined plane (seed, data.md 3), in the ramp frame: x along the ramp
// (down-slope), y normal to it, gravity (g sin a, -g cos a). The bottom box face is the ramp (no
// slip: chips glued on); the bin is the stretch 0 <= x <= bin length on it with a free-slip
// back wall (left face); the gate is a free-slip plate normal to the ramp, 2 cells thick, closed
// during the gravity phase and lifted at 1 m/s to the opening at the event; the right face (end
// of the ramp) is an outflow that books what runs off.
#include "fullsim/cel/cel_scene.hpp"
#include "models/equipment/chute.hpp"

namespace feedflow::cel {

inline constexpr double kGateLiftSpeed = 1.0;  // [m/s], assumed (the seed does not give it)

CelScene make_chute_scene(const Chute& chute, const SceneMaterial& material, double cell_size);

}  // namespace feedflow::cel
