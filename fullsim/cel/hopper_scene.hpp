#pragma once
// The CEL scene of a wedge hopper (seed FEM deck, data.md 2.1-2.2), as a half slice or as the
// full-width section, or of a conical hopper on the axisymmetric grid: the half slice's
// geometry in (r, z), the axis in place of the symmetry plane, the cone's wall and the bin's
// cylinder, the circular outlet on the axis (section_depth_factor 2 pi). Half slice (the seed's): the symmetry plane at x = 0 (free-slip left face),
// the inclined wall from the outlet edge (W/2, 0) to the bin wall, the vertical bin wall above.
// Full width: the bin walls at x = 0 and x = bin_width, the centre line at bin_width / 2, two
// mirror-image inclined walls; the grid is the half slice's mirrored about the centre line (one
// cell beyond each bin wall). Either way: Coulomb friction at the wall friction angle, each
// inclined wall continued straight down below the outlet plane (so the bottom row beside the
// outlet is solid and only the outlet gap lets material out), the outlet on the bottom box face
// (outflow: the mass leaving is booked) closed by a gate wall during the gravity phase and
// removed at the event, material filling the section to the fill height above the virtual apex.
// The side walls lie 1e-9 h off the material, so that no node is on a wall or at exactly
// the contact distance h/2 from it, where round-off would decide the contact (differently on
// the two walls of the full section).
#include "fullsim/cel/cel_scene.hpp"
#include "models/equipment/hopper.hpp"

namespace feedflow::cel {

enum class HopperSection {
  half,  // symmetry plane at the centre line, section_depth_factor 2
  full,  // both walls, section_depth_factor 1
};

// Throws std::invalid_argument for h <= 0 or a conical hopper's full section.
CelScene make_hopper_scene(const Hopper& hopper, double wall_friction_angle,
                           const SceneMaterial& material, double cell_size,
                           HopperSection section = HopperSection::half);

// x of the hopper's centre line in the scene's coordinates: 0 (the symmetry plane) for the half
// slice, bin_width / 2 for the full section [m].
double hopper_centre_line(const Hopper& hopper, HopperSection section);

// "half" or "full" (the [cel] hopper_section key's values).
const char* hopper_section_name(HopperSection section);

}  // namespace feedflow::cel
