// The hypoplastic hot path: one rate evaluation (target < 150 ns) and one integrated
// material-point step at CEL increments ||D|| dt ~ 1e-5..1e-4 (target < 1 us).
#include <benchmark/benchmark.h>

#include "models/hypoplastic/element_tests.hpp"
#include "models/hypoplastic/material_point_integrator.hpp"
#include "models/hypoplastic/stress_rate.hpp"

namespace {

using namespace feedflow;

Eigen::Matrix3d typical_stretching() {  // ||D|| = 1, with shear
  Eigen::Matrix3d d;
  d << -0.8, 0.3, 0.05, 0.3, 0.3, -0.1, 0.05, -0.1, 0.2;
  return d / tensor_norm(d);
}

void HypoplasticRateEvaluation(benchmark::State& state) {
  const auto model = make_hypoplastic_model(loblolly_pine_table1(),
                                            static_cast<HypoplasticVariant>(state.range(0)));
  Eigen::Matrix3d t;
  t << -2.6e3, 150.0, 20.0, 150.0, -1.9e3, -40.0, 20.0, -40.0, -1.5e3;
  const Eigen::Matrix3d d = typical_stretching();
  double e = 0.75;
  for (auto _ : state) {
    benchmark::DoNotOptimize(t);
    benchmark::DoNotOptimize(e);
    Eigen::Matrix3d rate = stress_rate(model, t, e, d);
    benchmark::DoNotOptimize(rate);
  }
}
BENCHMARK(HypoplasticRateEvaluation)->Arg(0)->Arg(1)->ArgName("variant");  // 0 G-B, 1 vW

// One CEL step: Hughes-Winget rotation, safeguards, Heun substep(s) with error control.
void HypoplasticMaterialPointStep(benchmark::State& state) {
  const auto model = make_hypoplastic_model(loblolly_pine_table1());
  const double strain_per_step = 1e-5 * static_cast<double>(state.range(0));
  const Eigen::Matrix3d d = typical_stretching();
  Eigen::Matrix3d w = Eigen::Matrix3d::Zero();
  w(0, 1) = 0.4;
  w(1, 0) = -0.4;
  MaterialPointState s = isotropic_state(2e3, 0.75);
  long substeps = 0, steps = 0;
  for (auto _ : state) {
    // Alternate loading and unloading every 1000 steps so the state stays near 2 kPa.
    const double sign = (steps++ / 1000) % 2 ? -1.0 : 1.0;
    substeps += integrate_material_point(model, s, sign * d, w, strain_per_step).substeps;
    benchmark::DoNotOptimize(s);
  }
  state.counters["substeps_per_step"] = static_cast<double>(substeps) / static_cast<double>(steps);
}
BENCHMARK(HypoplasticMaterialPointStep)->Arg(1)->Arg(3)->Arg(10)->ArgName("strain_x1e-5");

}  // namespace
