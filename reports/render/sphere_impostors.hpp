#pragma once
// Particles drawn as sphere impostors: one camera-facing quad per sphere (instanced, four
// vertices from gl_VertexID), the fragment shader cutting the disc, lighting the sphere's
// surface normal and writing the true surface depth, so intersecting spheres meet correctly.
// Exact spheres at any size for 20 bytes per particle. Internal to reports/render.
#include <span>

#include "reports/render/camera.hpp"
#include "reports/render/colour_map.hpp"
#include "reports/render/gl_program.hpp"
#include "reports/render/offscreen_context.hpp"

namespace feedflow::render {

class SphereImpostors {
 public:
  explicit SphereImpostors(const OffscreenContext& context);
  ~SphereImpostors();
  SphereImpostors(const SphereImpostors&) = delete;
  SphereImpostors& operator=(const SphereImpostors&) = delete;

  // Draws particle i in colour colours[i] into the bound target, depth-tested. Positions go to
  // the GPU relative to the camera centre, so float precision holds far from the origin.
  void draw(const ParticleSet& particles, std::span<const Rgb8> colours, const Camera& camera);

 private:
  const GlApi& gl_;
  GlProgram program_;
  GLuint vertex_array_ = 0;
  GLuint buffer_ = 0;
};

}  // namespace feedflow::render
