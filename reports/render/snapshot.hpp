#pragma once
// Off-screen rendered snapshots of a scene: the public face of reports/render.
//
//   render::Scene scene;                       // particles, a field, walls, meshes (scene.hpp)
//   render::SnapshotOptions options;           // size, camera preset, colouring, legend
//   render::SnapshotRenderer renderer;         // owns the OSMesa context; reuse it
//   render::Snapshot shot = renderer.render(scene, options);
//   render::write_png(shot.image, "out/hopper_t2s.png");
//
// Rendering runs on Mesa's software rasteriser (no display, no GPU) and is deterministic: the
// same scene and options give the same pixels.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "reports/render/camera.hpp"
#include "reports/render/colour_map.hpp"
#include "reports/render/rgba_image.hpp"
#include "reports/render/scene.hpp"
#include "reports/render/snapshot_layout.hpp"

namespace feedflow::render {

enum class ParticleColouring {
  by_value,  // the colour scale over ParticleSet::value (uniform grey when there are none)
  by_layer,  // the qualitative layer colours over ParticleSet::layer
  uniform,   // all particles in `particle_colour`
};

struct SnapshotOptions {
  int width = 1600;
  int height = 1200;
  CameraPreset preset = CameraPreset::front;
  std::optional<Camera> camera;  // replaces the preset and the automatic fit when set
  ParticleColouring colouring = ParticleColouring::by_value;
  Rgb8 particle_colour{170, 170, 170};
  // The scalar shown (particle values and field cells share one scale and one colour bar).
  std::string quantity = "speed";
  std::string unit = "m/s";
  std::optional<double> value_lo;  // colour range; by default the range of the data shown
  std::optional<double> value_hi;
  int supersampling = 2;  // anti-aliasing: s x s samples per pixel, box-filtered (1..4)
  Rgb8 background{255, 255, 255};
  Rgb8 wall_colour{40, 40, 40};
  Rgb8 outline_colour{0, 0, 0};
  Rgb8 mesh_colour{190, 190, 190};
  double wall_width_pixels = 2.0;
  bool legend = true;     // colour bar (or layer legend) in a panel on the right
  bool scale_bar = true;  // length bar in the lower-left corner (not for an empty scene)
};

struct Snapshot {
  RgbaImage image;
  Camera camera;                     // as used, after the fit
  SnapshotLayout layout;             // where the scene, legend and colour bar are
  std::optional<ColourScale> scale;  // the colour scale shown, if any

  // Where a world point lands in `image` (pixels, y down).
  ImagePoint pixel_of(Vec3 p) const;
};

class SnapshotRenderer {
 public:
  // Creates the off-screen OpenGL context; throws NotAvailable if libOSMesa cannot be loaded,
  // std::runtime_error if OSMesa cannot create the context.
  SnapshotRenderer();
  ~SnapshotRenderer();
  SnapshotRenderer(const SnapshotRenderer&) = delete;
  SnapshotRenderer& operator=(const SnapshotRenderer&) = delete;

  // Throws std::invalid_argument for inconsistent scene data or options, std::runtime_error when
  // OpenGL or cairo fails. Call from one thread at a time.
  Snapshot render(const Scene& scene, const SnapshotOptions& options);

  // The OpenGL version and renderer strings of the off-screen context.
  std::string gl_version() const;
  std::string gl_renderer() const;

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

// One-off convenience: a renderer for a single snapshot.
Snapshot render_snapshot(const Scene& scene, const SnapshotOptions& options);

}  // namespace feedflow::render
