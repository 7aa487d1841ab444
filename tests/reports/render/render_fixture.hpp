#pragma once
// Shared pieces of the renderer tests: one off-screen context for the whole test program (it
// takes a moment to create) and small synthetic scenes.
#include <cstdint>
#include <cstdlib>

#include "reports/render/snapshot.hpp"

namespace feedflow::render::testing {

inline SnapshotRenderer& shared_renderer() {
  static SnapshotRenderer renderer;
  return renderer;
}

// |a - b| <= tolerance in each channel.
inline bool near(Rgba8 a, Rgb8 b, int tolerance) {
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
         std::abs(a.b - b.b) <= tolerance;
}

// A quasi-2-D slab of `n` overlapping spheres in a box 0.2 m wide and 0.3 m high, with two
// side walls and a floor, and a pseudo-random (fixed-seed) speed per particle.
inline Scene packed_slab(int n) {
  Scene scene;
  std::uint64_t state = 12345;
  const auto uniform = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / static_cast<double>(1ull << 53);
  };
  for (int i = 0; i < n; ++i) {
    scene.particles.x.push_back(0.2 * uniform());
    scene.particles.y.push_back(0.3 * uniform());
    scene.particles.z.push_back(0.01 * uniform());
    scene.particles.radius.push_back(0.002 + 0.002 * uniform());
    scene.particles.value.push_back(2.0 * uniform());
    scene.particles.layer.push_back(static_cast<std::int32_t>(scene.particles.y.back() / 0.05));
  }
  scene.segments.push_back({{0.0, 0.0, 0.0}, {0.0, 0.32, 0.0}});
  scene.segments.push_back({{0.2, 0.0, 0.0}, {0.2, 0.32, 0.0}});
  scene.segments.push_back({{0.0, 0.0, 0.0}, {0.2, 0.0, 0.0}});
  return scene;
}

}  // namespace feedflow::render::testing
