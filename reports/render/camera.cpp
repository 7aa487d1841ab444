#include "reports/render/camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace feedflow::render {

ImagePoint project(const Camera& camera, Vec3 p, int width, int height) {
  const Vec3 d = p - camera.centre;
  const double u = dot(d, camera.right()) / camera.half_width;  // -1 .. 1, left to right
  const double v = dot(d, camera.up) / camera.half_height;      // -1 .. 1, bottom to top
  const double w = dot(d, camera.forward) / camera.half_depth;  // -1 .. 1, near to far
  return {0.5 * (u + 1.0) * width, 0.5 * (1.0 - v) * height, 0.5 * (w + 1.0)};
}

Camera preset_orientation(CameraPreset preset, const Scene& scene) {
  Camera camera;
  if (preset == CameraPreset::front) return camera;
  const Vec3 axis =
      scene.cylinders.empty() ? Vec3{0.0, 0.0, 1.0} : normalised(scene.cylinders.front().axis);
  camera.forward = -axis;
  // Up: world y made perpendicular to the axis; world z when the axis is vertical.
  Vec3 up = Vec3{0.0, 1.0, 0.0} - axis.y * axis;
  if (length(up) < 1e-6) up = Vec3{0.0, 0.0, 1.0} - axis.z * axis;
  camera.up = normalised(up);
  return camera;
}

Camera fit_camera(Camera oriented, const Bounds3& bounds, double aspect, double margin) {
  Camera camera = oriented;
  if (bounds.empty()) {
    camera.centre = {};
    camera.half_height = 1.0;
    camera.half_width = aspect;
    camera.half_depth = 1.0;
    return camera;
  }
  const Vec3 right = camera.right();
  std::array<double, 3> lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::max()};
  std::array<double, 3> hi{-lo[0], -lo[1], -lo[2]};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{(corner & 1) ? bounds.hi.x : bounds.lo.x, (corner & 2) ? bounds.hi.y : bounds.lo.y,
                 (corner & 4) ? bounds.hi.z : bounds.lo.z};
    const std::array<double, 3> c{dot(p, right), dot(p, camera.up), dot(p, camera.forward)};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
  }
  const double mid_r = 0.5 * (lo[0] + hi[0]);
  const double mid_u = 0.5 * (lo[1] + hi[1]);
  const double mid_f = 0.5 * (lo[2] + hi[2]);
  camera.centre = mid_r * right + mid_u * camera.up + mid_f * camera.forward;

  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-9});
  double half_w = 0.5 * (hi[0] - lo[0]) + margin * extent;
  double half_h = 0.5 * (hi[1] - lo[1]) + margin * extent;
  if (half_w < half_h * aspect)
    half_w = half_h * aspect;
  else
    half_h = half_w / aspect;
  camera.half_width = half_w;
  camera.half_height = half_h;
  // A little slack in depth so that the nearest sphere surface stays inside the clip volume.
  camera.half_depth = 0.5 * (hi[2] - lo[2]) * 1.05 + 1e-3 * extent;
  return camera;
}

}  // namespace feedflow::render
