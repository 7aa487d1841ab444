#pragma once
// The seed's glued-chip ramp as geometry (inclined_plane_scene.hpp): a saw-tooth of 45 deg
// faces, one particle diameter in period and one radius high, in the ramp's frame (x down the
// slope, z normal to it, crests at z = R). A sphere resting in a groove cannot slide without
// climbing a 45 deg face, which a flow at the seed's angles cannot drive: the base is no-slip.
// The teeth span [from, to) along the slope (whole periods from `from`) and y over three slab
// depths from -depth, so the images of a periodic slab meet them too.
#include "fullsim/dem/triangle_mesh.hpp"

namespace feedflow {

TriangleMesh sawtooth_ramp(double from, double to, double radius, double depth);

// A rectangle from a to b (along the slope, at their heights) spanning y over three slab
// depths from -depth, as triangles `n` and `n + 1` of `m` (n advanced): a plate of the scene.
void add_slab_strip(TriangleMesh& m, const Vec3& a, const Vec3& b, double depth, std::size_t& n);

}  // namespace feedflow
