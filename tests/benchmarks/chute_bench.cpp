// L1 chute model: the seed's inclined-plane test (2 m ramp at 29.5 deg, 0.57 m bin filled to
// 0.5 m, 0.22 m gate) released and run to rest. Target: under 1 s.
#include <benchmark/benchmark.h>

#include <numbers>

#include "models/chute/chute_release.hpp"

namespace {

void ChuteL1ReleaseToRest(benchmark::State& state) {
  using namespace feedflow;
  constexpr double kDeg = std::numbers::pi / 180.0;
  Chute c;
  c.angle = 29.5 * kDeg;
  c.width = 0.76;
  c.length = 2.0;
  c.gate_opening = 0.22;
  c.bin_length = 0.57;
  c.bin_height = 0.915;
  c.fill_height = 0.5;
  const PouliquenLaw law{27 * kDeg, 40 * kDeg, 10e-3, 0.136, 0.0};
  ChuteReleaseOptions o;
  o.cell_size = static_cast<double>(state.range(0)) * 1e-3;
  RampFlowResult r;
  for (auto _ : state) {
    r = run_chute_release(c, law, o);
    benchmark::DoNotOptimize(r.probe_thickness);
  }
  state.counters["cells"] = static_cast<double>(r.x.size());
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["t_stop_s"] = r.stop_time;
  state.counters["h_mid_mm"] = r.probe_thickness * 1e3;
}
BENCHMARK(ChuteL1ReleaseToRest)->Arg(20)->Arg(10)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace
