#include "fullsim/dem/scene/slab_faces.hpp"

namespace feedflow {
namespace {
constexpr std::string_view kKeywords[] = {"frictional", "frictionless", "periodic", "planar"};
}  // namespace

std::span<const std::string_view> slab_face_keywords() { return kKeywords; }

std::optional<SlabFaces> slab_faces_from_keyword(std::string_view keyword) {
  if (keyword.empty()) return SlabFaces::automatic;
  if (keyword == kKeywords[0]) return SlabFaces::frictional;
  if (keyword == kKeywords[1]) return SlabFaces::frictionless;
  if (keyword == kKeywords[2]) return SlabFaces::periodic;
  if (keyword == kKeywords[3]) return SlabFaces::planar;
  return std::nullopt;
}

const char* to_string(SlabFaces faces) {
  switch (faces) {
    case SlabFaces::frictional: return "frictional";
    case SlabFaces::frictionless: return "frictionless";
    case SlabFaces::periodic: return "periodic";
    case SlabFaces::planar: return "planar";
    case SlabFaces::automatic: break;
  }
  return "automatic";
}

}  // namespace feedflow
