// DEM engine throughput (particle-steps per second): a settled bed of 30 000 pine spheres
// (seed Table 2: R = 1.5 mm, rho = 390 kg/m^3, P-P and P-W sets) in a box periodic in x and y
// with a floor and gravity, with Hertz + Mindlin + cdt and with hysteretic_nonlinear2 +
// history + cdt, each at its own stable step, on 1 and 2 OpenMP threads (second argument).
//   build/tests/feedflow_benchmarks --benchmark_filter=DemBed30k
// (on a shared machine add OMP_WAIT_POLICY=passive; the bed is built and settled once per law,
// 1500 steps, before the first timing of that law). DemChute30k (below) is the same bed on a
// 30 deg slope, the "granular chute".
#include <benchmark/benchmark.h>

#include <omp.h>

#include <iomanip>
#include <iostream>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <tuple>

#include "fullsim/dem/dem_engine.hpp"
#include "models/units/angle.hpp"
#include "tests/support/pine_table2.hpp"

namespace {

using namespace feedflow;

DemContactParameters pine(double friction, double rolling_friction) {  // seed Table 2
  return testing::pine_table2_contact(friction, rolling_friction);
}

constexpr int kNx = 40, kNy = 25, kNz = 30;  // 30 000 spheres
constexpr double kRadius = 1.5e-3;

// A bed of kNx x kNy x kNz spheres stacked on a floor (lattice jittered by 2 % of R), settled
// for 1500 steps; built once per law, tilt and `copy` (the chute builds one per thread count, so
// that each case times steps 1501-2500 of its own flow, as the peers do). `tilt` turns gravity
// from -z toward +x [deg] (0: the settled bed; 30: the chute, periodic in x).
DemEngine& settled_bed(int law, int tilt = 0, int copy = 0) {
  static std::map<std::tuple<int, int, int>, std::unique_ptr<DemEngine>> beds;
  auto& bed = beds[{law, tilt, copy}];
  if (bed) return *bed;
  DemSettings s;
  s.material.particle = {kRadius, 390.0};
  s.material.particle_particle = pine(0.5, 0.8);
  s.material.particle_wall = pine(0.2, 0.6);
  s.law = law == 0 ? choose_contact_law("hertz", "mindlin", "cdt", "none")
                   : choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "none");
  const double a = tilt * kDegree;
  s.gravity = 9.81 * Vec3(std::sin(a), 0.0, -std::cos(a));
  const double spacing = 2.0 * kRadius;
  SimulationBox box{Vec3::Zero(), Vec3(kNx * spacing, kNy * spacing, (kNz + 4) * spacing),
                    {true, true, false}};
  ParticleStore p;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i) {
        const Vec3 jitter = 0.02 * kRadius * Vec3(u(rng), u(rng), 0.0);
        p.add(Vec3((i + 0.5) * spacing, (j + 0.5) * spacing, kRadius + k * spacing * 1.001) + jitter,
              kRadius, 390.0, k);
      }
  bed = std::make_unique<DemEngine>(s, box, std::move(p));
  bed->add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  bed->prepare(std::cerr);
  bed->run_steps(1500);
  // 17 digits: two builds that should agree bit for bit can be compared by this line.
  std::cerr << std::setprecision(17) << "settled: max speed " << bed->max_speed()
            << " m/s, kinetic energy " << bed->kinetic_energy() << " J\n"
            << bed->performance_report();
  return *bed;
}

void DemBed30k(benchmark::State& state) {
  const int law = static_cast<int>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  DemEngine& bed = settled_bed(law);
  const double before = bed.particle_steps();
  constexpr long kSteps = 100;
  for (auto _ : state) bed.run_steps(kSteps);
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(bed.particle_steps() - before, benchmark::Counter::kIsRate);
  state.counters["particles"] = static_cast<double>(bed.particles().size());
  state.counters["pairs_per_particle"] =
      static_cast<double>(bed.neighbours().pair_count()) / static_cast<double>(bed.particles().size());
  state.counters["dt_us"] = bed.time_step() * 1e6;
  state.SetLabel(law == 0 ? "hertz+mindlin+cdt" : "hysteretic_nonlinear2+history+cdt");
}

BENCHMARK(DemBed30k)
    ->ArgNames({"law", "threads"})
    ->Args({0, 1})
    ->Args({0, 2})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

// The chute of issue 5: the same bed with gravity tilted 30 deg toward +x (periodic in x), so
// it flows down-slope over the frictional floor. A fresh chute per case, 1500 steps from rest,
// then 1000 timed steps (10 x 100), as tests/benchmarks/peers/run_peers.sh with TILT=30;
// `vx_m_per_s` is the mean down-slope speed at the end.
//   build/tests/feedflow_benchmarks --benchmark_filter=DemChute30k
void DemChute30k(benchmark::State& state) {
  const int law = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  DemEngine& chute = settled_bed(law, 30, threads);
  const double before = chute.particle_steps();
  for (auto _ : state) chute.run_steps(100);
  const ParticleStore& p = chute.particles();
  double momentum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) momentum += p.mass[i] * p.velocity[i].x();
  state.counters["particle_steps_per_s"] =
      benchmark::Counter(chute.particle_steps() - before, benchmark::Counter::kIsRate);
  state.counters["vx_m_per_s"] = momentum / p.total_mass();
  state.counters["dt_us"] = chute.time_step() * 1e6;
  state.SetLabel(law == 0 ? "chute 30 deg, hertz+mindlin+cdt"
                          : "chute 30 deg, hysteretic_nonlinear2+history+cdt");
}

BENCHMARK(DemChute30k)
    ->ArgNames({"law", "threads"})
    ->Args({0, 1})
    ->Args({0, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(10);

}  // namespace
