#pragma once
// The orthographic camera as the 4 x 4 matrix OpenGL wants (row-major here; upload with
// transpose), for positions given relative to the camera centre. Internal to reports/render.
#include <array>

#include "reports/render/camera.hpp"

namespace feedflow::render {

inline std::array<float, 16> view_projection(const Camera& c) {
  const Vec3 r = (1.0 / c.half_width) * c.right();
  const Vec3 u = (1.0 / c.half_height) * c.up;
  const Vec3 f = (1.0 / c.half_depth) * c.forward;
  const auto F = [](double v) { return static_cast<float>(v); };
  return {F(r.x), F(r.y), F(r.z), 0.0f,  //
          F(u.x), F(u.y), F(u.z), 0.0f,  //
          F(f.x), F(f.y), F(f.z), 0.0f,  //
          0.0f,   0.0f,   0.0f,   1.0f};
}

}  // namespace feedflow::render
