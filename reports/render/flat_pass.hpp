#pragma once
// Draws FlatTriangles: one colour per vertex, no lighting on the GPU. Internal to
// reports/render.
#include "reports/render/flat_geometry.hpp"
#include "reports/render/gl_program.hpp"
#include "reports/render/offscreen_context.hpp"

namespace feedflow::render {

class FlatPass {
 public:
  explicit FlatPass(const OffscreenContext& context);
  ~FlatPass();
  FlatPass(const FlatPass&) = delete;
  FlatPass& operator=(const FlatPass&) = delete;

  // Draws into the bound target with the current depth state.
  void draw(const FlatTriangles& triangles, const Camera& camera);

 private:
  const GlApi& gl_;
  GlProgram program_;
  GLuint vertex_array_ = 0;
  GLuint buffer_ = 0;
};

}  // namespace feedflow::render
