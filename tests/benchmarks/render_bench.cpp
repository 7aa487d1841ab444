// Snapshot rendering speed: 200 000 spheres at 1600 x 1200 (issue 8 asks for under 5 s).
//   build/tests/feedflow_benchmarks --benchmark_filter=Render
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>

#include "reports/render/snapshot.hpp"

namespace {

using namespace feedflow::render;

// A quasi-2-D hopper slab 0.4 m wide, 0.6 m high and 0.02 m deep holding `n` spheres of
// radius 1.2 to 1.8 mm at pseudo-random (fixed-seed) positions, coloured by a made-up speed, with
// its walls.
Scene hopper_slab(int n) {
  Scene scene;
  ParticleSet& p = scene.particles;
  p.x.reserve(n);
  p.y.reserve(n);
  p.z.reserve(n);
  p.radius.reserve(n);
  p.value.reserve(n);
  std::uint64_t state = 2024;
  const auto uniform = [&state] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) / static_cast<double>(1ull << 53);
  };
  for (int i = 0; i < n; ++i) {
    const double y = 0.6 * uniform();
    // Converging section below y = 0.25 m: half-width from 0.03 m at the outlet to 0.2 m.
    const double half = y < 0.25 ? 0.03 + 0.17 * y / 0.25 : 0.2;
    p.x.push_back(half * (2.0 * uniform() - 1.0));
    p.y.push_back(y);
    p.z.push_back(0.02 * uniform());
    p.radius.push_back(0.0012 + 0.0006 * uniform());
    p.value.push_back(1.5 * (1.0 - y / 0.6) * uniform());
  }
  scene.segments = {{{-0.03, 0.0, 0.0}, {-0.2, 0.25, 0.0}},
                    {{0.03, 0.0, 0.0}, {0.2, 0.25, 0.0}},
                    {{-0.2, 0.25, 0.0}, {-0.2, 0.62, 0.0}},
                    {{0.2, 0.25, 0.0}, {0.2, 0.62, 0.0}}};
  return scene;
}

// One snapshot with the renderer (the OpenGL context) already made: what a report with several
// snapshots pays per image.
void BM_RenderSpheres(benchmark::State& state) {
  const Scene scene = hopper_slab(static_cast<int>(state.range(0)));
  SnapshotOptions options;  // 1600 x 1200, 2 x 2 supersampling
  SnapshotRenderer renderer;
  for (auto _ : state) {
    Snapshot shot = renderer.render(scene, options);
    benchmark::DoNotOptimize(shot.image.pixels.data());
  }
  state.counters["spheres"] = static_cast<double>(state.range(0));
  state.SetLabel(renderer.gl_renderer());
}
BENCHMARK(BM_RenderSpheres)
    ->Arg(200000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();

// The whole job for one image: context creation, rendering and the PNG file.
void BM_RenderSpheresToPng(benchmark::State& state) {
  const Scene scene = hopper_slab(static_cast<int>(state.range(0)));
  const auto file = std::filesystem::temp_directory_path() / "feedflow_render_bench.png";
  for (auto _ : state) {
    const Snapshot shot = render_snapshot(scene, SnapshotOptions{});
    write_png(shot.image, file);
  }
  std::filesystem::remove(file);
}
BENCHMARK(BM_RenderSpheresToPng)
    ->Arg(200000)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2)
    ->UseRealTime();

}  // namespace
