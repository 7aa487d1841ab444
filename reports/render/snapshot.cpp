#include "reports/render/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "reports/render/flat_geometry.hpp"
#include "reports/render/flat_pass.hpp"
#include "reports/render/free_surface.hpp"
#include "reports/render/legend_overlay.hpp"
#include "reports/render/offscreen_context.hpp"
#include "reports/render/sphere_impostors.hpp"

namespace feedflow::render {

struct SnapshotRenderer::Context {
  OffscreenContext gl;
  SphereImpostors spheres{gl};
  FlatPass flat{gl};
};

namespace {

// The colour scale of the values shown, or none when nothing is coloured by value.
std::optional<ColourScale> colour_scale(const Scene& scene, const SnapshotOptions& options) {
  const ParticleSet& p = scene.particles;
  const bool particle_values =
      options.colouring == ParticleColouring::by_value && p.size() > 0 && !p.value.empty();
  if (!particle_values && !scene.field) return std::nullopt;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  const auto include = [&](double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  };
  if (particle_values) std::for_each(p.value.begin(), p.value.end(), include);
  if (scene.field) {
    const FieldGrid& f = *scene.field;
    for (std::size_t k = 0; k < f.value.size(); ++k) {
      if (f.volume_fraction[k] >= f.fill_threshold) include(f.value[k]);
    }
  }
  if (lo > hi) {
    lo = 0.0;
    hi = 1.0;
  }
  ColourScale scale{options.quantity, options.unit, options.value_lo.value_or(lo),
                    options.value_hi.value_or(hi)};
  if (!(scale.hi >= scale.lo) || !std::isfinite(scale.lo) || !std::isfinite(scale.hi)) {
    throw std::invalid_argument("snapshot colour range [" + std::to_string(scale.lo) + ", " +
                                std::to_string(scale.hi) + "] is not an interval");
  }
  return scale;
}

std::vector<Rgb8> particle_colours(const ParticleSet& p, const SnapshotOptions& options,
                                   const std::optional<ColourScale>& scale) {
  std::vector<Rgb8> colours(p.size(), options.particle_colour);
  if (options.colouring == ParticleColouring::by_value && !p.value.empty() && scale) {
    for (std::size_t i = 0; i < p.size(); ++i) colours[i] = scale->colour(p.value[i]);
  } else if (options.colouring == ParticleColouring::by_layer && !p.layer.empty()) {
    for (std::size_t i = 0; i < p.size(); ++i) colours[i] = layer_colour(p.layer[i]);
  }
  return colours;
}

// Averages each s x s block of `big` into one pixel.
RgbaImage box_filter(const RgbaImage& big, int s) {
  if (s == 1) return big;
  RgbaImage small(big.width / s, big.height / s);
  const int n = s * s;
  for (int y = 0; y < small.height; ++y) {
    for (int x = 0; x < small.width; ++x) {
      int sum[4] = {0, 0, 0, 0};
      for (int dy = 0; dy < s; ++dy) {
        const std::uint8_t* row =
            &big.pixels[4 * (static_cast<std::size_t>(y * s + dy) * big.width + x * s)];
        for (int k = 0; k < 4 * s; ++k) sum[k & 3] += row[k];
      }
      const std::size_t out = 4 * (static_cast<std::size_t>(y) * small.width + x);
      for (int c = 0; c < 4; ++c)
        small.pixels[out + c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
    }
  }
  return small;
}

}  // namespace

ImagePoint Snapshot::pixel_of(Vec3 p) const {
  ImagePoint q = project(camera, p, layout.scene.width, layout.scene.height);
  q.x += layout.scene.x;
  q.y += layout.scene.y;
  return q;
}

SnapshotRenderer::SnapshotRenderer() : context_(std::make_unique<Context>()) {}
SnapshotRenderer::~SnapshotRenderer() = default;

std::string SnapshotRenderer::gl_version() const { return context_->gl.version(); }
std::string SnapshotRenderer::gl_renderer() const { return context_->gl.renderer(); }

Snapshot SnapshotRenderer::render(const Scene& scene, const SnapshotOptions& options) {
  scene.particles.check();
  if (scene.field) scene.field->check();
  for (const TriangleMesh& m : scene.meshes) m.check();
  if (options.supersampling < 1 || options.supersampling > 4) {
    throw std::invalid_argument("snapshot supersampling must be 1 to 4, not " +
                                std::to_string(options.supersampling));
  }

  Snapshot shot;
  shot.scale = colour_scale(scene, options);
  std::vector<std::int32_t> layers;
  if (options.colouring == ParticleColouring::by_layer) {
    const std::set<std::int32_t> distinct(scene.particles.layer.begin(),
                                          scene.particles.layer.end());
    layers.assign(distinct.begin(), distinct.end());
  }
  const bool colour_bar = options.legend && shot.scale.has_value();
  shot.layout = snapshot_layout(options.width, options.height,
                                colour_bar || (options.legend && !layers.empty()), colour_bar);
  const PixelRect& area = shot.layout.scene;
  const double aspect = static_cast<double>(area.width) / area.height;
  shot.camera = options.camera ? *options.camera
                               : fit_camera(preset_orientation(options.preset, scene),
                                            scene_bounds(scene), aspect);
  if (options.camera &&
      std::abs(shot.camera.half_width / shot.camera.half_height - aspect) > 1e-3 * aspect) {
    // Keep pixels square: widen the given camera to the viewport's aspect.
    shot.camera.half_width = shot.camera.half_height * aspect;
  }

  // Supersampling, reduced if the context cannot hold the enlarged image.
  OffscreenContext& gl = context_->gl;
  gl.make_current();
  int s = options.supersampling;
  while (s > 1 && std::max(area.width, area.height) * s > gl.max_size()) --s;

  const std::vector<Rgb8> colours = particle_colours(scene.particles, options, shot.scale);
  const double pixel = metres_per_pixel(shot.camera, area.height * s);
  FlatTriangles solid(shot.camera, pixel * options.wall_width_pixels * s);
  FlatTriangles lines(shot.camera, pixel * options.wall_width_pixels * s);
  if (scene.field) {
    solid.add_field_cells(*scene.field, *shot.scale);
    lines.add_outline(free_surface_outline(*scene.field), scene.field->plane_z,
                      options.outline_colour);
  }
  for (const TriangleMesh& m : scene.meshes) solid.add_mesh(m, options.mesh_colour);
  lines.add_walls(scene, options.wall_colour);

  RgbaImage rendered;
  {
    RenderTarget target(gl, area.width * s, area.height * s);
    target.bind();
    const auto& api = gl.gl();
    api.ClearColor(options.background.r / 255.0f, options.background.g / 255.0f,
                   options.background.b / 255.0f, 1.0f);
    api.ClearDepth(1.0);
    api.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    api.Enable(GL_DEPTH_TEST);
    api.DepthFunc(GL_LEQUAL);  // of two coplanar pieces (a mesh on the field plane), the later wins
    context_->flat.draw(solid, shot.camera);
    context_->spheres.draw(scene.particles, colours, shot.camera);
    // Walls and the free surface stay visible in front of everything.
    api.Disable(GL_DEPTH_TEST);
    context_->flat.draw(lines, shot.camera);
    api.Finish();
    gl.check("snapshot rendering");
    rendered = box_filter(target.read(), s);
    gl.check("snapshot read-back");
  }

  shot.image = RgbaImage(options.width, options.height);
  const Rgba8 background{options.background.r, options.background.g, options.background.b, 255};
  for (int y = 0; y < options.height; ++y) {
    for (int x = 0; x < options.width; ++x) shot.image.set(x, y, background);
  }
  for (int y = 0; y < area.height; ++y) {
    std::copy_n(
        &rendered.pixels[4 * static_cast<std::size_t>(y) * area.width], 4 * area.width,
        &shot.image.pixels[4 * (static_cast<std::size_t>(area.y + y) * options.width + area.x)]);
  }
  if (colour_bar) paint_colour_gradient(shot.image, shot.layout.colour_bar);
  LegendText legend;
  legend.scale = colour_bar ? &*shot.scale : nullptr;
  if (options.legend) legend.layers = layers;
  // An empty scene has nothing to measure, so no scale bar.
  const bool measured = options.scale_bar && !scene_bounds(scene).empty();
  legend.metres_per_pixel = measured ? metres_per_pixel(shot.camera, area.height) : 0.0;
  if (colour_bar || !legend.layers.empty() || legend.metres_per_pixel > 0.0) {
    draw_legend(shot.image, shot.layout, legend);
  }
  return shot;
}

Snapshot render_snapshot(const Scene& scene, const SnapshotOptions& options) {
  SnapshotRenderer renderer;
  return renderer.render(scene, options);
}

}  // namespace feedflow::render
