// L1 chute model: the seed's inclined-plane test (2 m ramp, 0.57 m bin filled to 0.5 m, 0.22 m
// gate) released and run to rest, at 29.5 deg and at 37 deg (the seed's two angles), on
// 20 / 10 / 5 mm cells. The designer uses 10 mm. Target: under 1 s.
#include <benchmark/benchmark.h>

#include "models/chute/chute_release.hpp"
#include "models/units/angle.hpp"

namespace {

// state.range(0): ramp angle in tenths of a degree; state.range(1): cell size in mm.
void ChuteL1ReleaseToRest(benchmark::State& state) {
  using namespace feedflow;
  Chute c;
  c.angle = static_cast<double>(state.range(0)) * 0.1 * kDegree;
  c.width = 0.76;
  c.length = 2.0;
  c.gate_opening = 0.22;
  c.bin_length = 0.57;
  c.bin_height = 0.915;
  c.fill_height = 0.5;
  const PouliquenLaw law{27 * kDegree, 40 * kDegree, 10e-3, 0.136, 0.0};
  ChuteReleaseOptions o;
  o.cell_size = static_cast<double>(state.range(1)) * 1e-3;
  RampFlowResult r;
  for (auto _ : state) {
    r = run_chute_release(c, law, o);
    benchmark::DoNotOptimize(r.probe_thickness);
  }
  state.counters["cells"] = static_cast<double>(r.x.size());
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["t_stop_s"] = r.stop_time;
  state.counters["h_mid_mm"] = r.probe_thickness * 1e3;
  state.counters["h_stop_mm"] = stopping_thickness(law, c.angle).thickness * 1e3;
}
BENCHMARK(ChuteL1ReleaseToRest)
    ->ArgNames({"angle_x10", "dx_mm"})
    ->ArgsProduct({{295, 370}, {20, 10, 5}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
