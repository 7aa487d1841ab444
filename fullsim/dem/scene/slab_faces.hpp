#pragma once
// The front and back faces of a quasi-2D DEM slab: frictional planes (the particle-wall
// Table 2 set), frictionless planes (that set without sliding and rolling friction: they hold
// the grains in the slab and take no shear, the usual stand-in for the slab's neighbours in
// the bulk), a periodic axis (no faces; the slab must be two neighbour cutoffs deep), or a
// planar layer (one layer of spheres held in its mid-plane, DemEngine::hold_in_plane: no
// faces, nothing crosses the slab). `automatic` keeps the scenes' earlier rule: periodic when
// deep enough, else frictional.
#include <optional>
#include <span>
#include <string_view>

namespace feedflow {

enum class SlabFaces { automatic, frictional, frictionless, periodic, planar };

// The case keywords ("frictional", "frictionless", "periodic", "planar"), in that order.
std::span<const std::string_view> slab_face_keywords();
// The choice named by a keyword; empty text is `automatic`, an unknown one none.
std::optional<SlabFaces> slab_faces_from_keyword(std::string_view keyword);
const char* to_string(SlabFaces faces);

}  // namespace feedflow
