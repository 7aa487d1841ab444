// Sphere-mesh contact queries (MeshWall::touches) per second, for the two meshes the scenes use
// most: the seed's saw-tooth ramp under a 15 mm slab (stopping layers, the inclined plane) and
// the pilot cone's wall (20 deg, 60 mm outlet, 0.3 m bin, a 90 deg sector). Spheres of the seed's
// radius at random places within reach of the mesh, as the wall loop queries the spheres its
// reach mask keeps.
//   build/tests/feedflow_benchmarks --benchmark_filter=MeshWallTouches
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "fullsim/dem/mesh_wall.hpp"
#include "fullsim/dem/scene/conical_hopper.hpp"
#include "fullsim/dem/scene/sawtooth_ramp.hpp"
#include "models/units/angle.hpp"

namespace {

using namespace feedflow;

constexpr double kRadius = 1.5e-3;
constexpr double kSkin = 0.45e-3;  // the engine's skin: 0.3 R

void query(benchmark::State& state, const MeshWall& mesh, const std::vector<Vec3>& at) {
  std::array<MeshTouch, MeshWall::kMaxContacts> touch;
  std::size_t k = 0;
  long contacts = 0;
  for (auto _ : state) {
    contacts += mesh.touches(at[k], kRadius, touch);
    k = k + 1 == at.size() ? 0 : k + 1;
  }
  benchmark::DoNotOptimize(contacts);
  state.SetItemsProcessed(state.iterations());
  state.counters["contacts_per_query"] =
      static_cast<double>(contacts) / static_cast<double>(state.iterations());
}

void MeshWallTouchesRamp(benchmark::State& state) {
  const double depth = 15e-3;
  const MeshWall ramp("ramp", sawtooth_ramp(-6e-3, 66e-3, kRadius, depth));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(0.0, 60e-3), y(0.0, depth),
      z(0.0, 2.0 * kRadius + kSkin);
  std::vector<Vec3> at(4096);
  for (auto& p : at) p = Vec3(x(rng), y(rng), z(rng));
  query(state, ramp, at);
}
BENCHMARK(MeshWallTouchesRamp);

void MeshWallTouchesCone(benchmark::State& state) {
  ConicalHopper h;
  h.semi_angle = 20.0 * kDegree;
  h.outlet_diameter = 0.06;
  h.bin_diameter = 0.3;
  h.fill_height = 0.5;
  h.sector = 90.0 * kDegree;
  h.radius = kRadius;
  const MeshWall cone = h.cone_mesh();
  // Centres within a radius and the skin of the cone's inner face, over the sector.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> height(0.0, h.bin_bottom()), turn(0.0, h.sector),
      inset(0.0, kRadius + kSkin);
  std::vector<Vec3> at(4096);
  for (auto& p : at) {
    const double z = height(rng), a = turn(rng) - 0.5 * h.sector;
    const double r = h.radius_at(z) - inset(rng) / std::cos(h.semi_angle);
    p = Vec3(r * std::cos(a), r * std::sin(a), z);
  }
  query(state, cone, at);
}
BENCHMARK(MeshWallTouchesCone);

}  // namespace
