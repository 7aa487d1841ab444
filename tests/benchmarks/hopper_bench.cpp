// Hopper reduced models: one design check (pattern + ff + B_c + rate) with the closed-form
// flow factor (target < 50 us) and with Jenike's radial stress field (target < 20 ms).
#include <benchmark/benchmark.h>

#include "models/hopper/critical_outlet.hpp"
#include "models/hopper/discharge_rate.hpp"
#include "models/hopper/enstad_flow_factor.hpp"
#include "models/hopper/flow_pattern.hpp"
#include "models/hopper/radial_stress_field.hpp"
#include "models/units/angle.hpp"

namespace {

using namespace feedflow;

// The seed wedge: 30 deg, phi_w 8.5 deg, delta 50 deg, B 60 mm, section 1.4 flow function.
double design_check(double ff) {
  const auto f = FlowFunction::linear(0.1, 50.0);
  const auto rho = BulkDensity::constant(290.0);
  const auto pattern =
      classify_flow_pattern(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree);
  const auto outlet = jenike_critical_outlet(FlowGeometry::plane, 30 * kDegree, ff, f, rho);
  const auto rate = johanson_discharge(FlowGeometry::plane, 30 * kDegree, 0.06, ff, f, rho);
  return outlet.width + rate.rate + pattern.margin;
}

void HopperClosedFormDesignCheck(benchmark::State& state) {
  for (auto _ : state) {
    const double ff =
        enstad_flow_factor(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree);
    benchmark::DoNotOptimize(design_check(ff));
  }
}
BENCHMARK(HopperClosedFormDesignCheck)->Unit(benchmark::kMicrosecond);

void HopperRadialStressFieldDesignCheck(benchmark::State& state) {
  for (auto _ : state) {
    const auto field =
        solve_radial_stress_field(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree);
    benchmark::DoNotOptimize(design_check(field->flow_factor));
  }
}
BENCHMARK(HopperRadialStressFieldDesignCheck)->Unit(benchmark::kMillisecond);

void HopperRadialStressFieldConical(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(solve_radial_stress_field(FlowGeometry::conical, 29.5 * kDegree,
                                                       40 * kDegree, 16 * kDegree));
}
BENCHMARK(HopperRadialStressFieldConical)->Unit(benchmark::kMillisecond);

}  // namespace
