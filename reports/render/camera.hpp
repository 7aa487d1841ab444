#pragma once
// The orthographic camera of a snapshot, its presets and the automatic fit to a scene.
// Engineering snapshots use parallel projection: sizes read the same everywhere in the image,
// so a scale bar is meaningful. Presets: the front view looks at a quasi-2-D slab (hopper,
// inclined plane) along -z with y up; the axial view looks down a drum's axis.
#include "reports/render/scene.hpp"

namespace feedflow::render {

enum class CameraPreset {
  front,  // along -z, y up: hopper and inclined-plane slabs
  axial,  // along the (first) drum axis, y up as far as possible
};

// The view volume is the box centred on `centre`, spanning +-half_width along right(),
// +-half_height along `up` and +-half_depth along `forward` (the viewing direction).
struct Camera {
  Vec3 centre;
  Vec3 forward{0.0, 0.0, -1.0};  // unit, from the viewer into the scene
  Vec3 up{0.0, 1.0, 0.0};        // unit, perpendicular to forward
  double half_width = 1.0;
  double half_height = 1.0;
  double half_depth = 1.0;

  Vec3 right() const { return cross(forward, up); }
};

// A point on the image: x to the right and y downwards from the top-left corner of the
// viewport, in pixels (pixel (i, j) covers [i, i+1) x [j, j+1)); depth in [0, 1], 0 nearest.
struct ImagePoint {
  double x = 0.0;
  double y = 0.0;
  double depth = 0.0;
};

// Where `p` lands in a viewport of width x height pixels.
ImagePoint project(const Camera& camera, Vec3 p, int width, int height);

// The viewing direction and up vector of a preset for this scene: the axial preset looks along
// the first cylinder's axis (the z axis when the scene has none).
Camera preset_orientation(CameraPreset preset, const Scene& scene);

// Centres `oriented` on `bounds` and sizes it to show all of them in a viewport of the given
// aspect ratio (width / height) with `margin` (a fraction of the larger extent) all round.
// An empty box gives a unit view around the origin.
Camera fit_camera(Camera oriented, const Bounds3& bounds, double aspect, double margin = 0.06);

// The world length covered by one pixel of a viewport `height` pixels high.
inline double metres_per_pixel(const Camera& camera, int height) {
  return 2.0 * camera.half_height / height;
}

}  // namespace feedflow::render
