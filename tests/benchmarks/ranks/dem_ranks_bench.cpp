// DEM throughput on MPI ranks: a bed of pine spheres (seed Table 2: R = 1.5 mm,
// rho = 390 kg/m^3) stacked on a floor in a box periodic in x and y, settled for 1 500 steps,
// then timed over the next steps; the same bed, the same steps on any rank count.
//   build/tests/dem_ranks_bench [PARTICLES] [STEPS] [hertz|seed]            (one rank)
//   mpirun -np 2 build/tests/dem_ranks_bench [PARTICLES] [STEPS] [hertz|seed]
// Rank 0 prints particle-steps per second (the whole run's) and per core, the plan, and each
// phase's time over the ranks. Compare rank counts side by side in one script on a quiet
// machine (RECORD.md, "DEM on ranks").
#include <mpi.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

#include "fullsim/dem/dem_engine.hpp"
#include "tests/support/pine_table2.hpp"

using namespace feedflow;

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  const DemRanks ranks = DemRanks::world();
  const long particles = argc > 1 ? std::atol(argv[1]) : 100000;
  const long steps = argc > 2 ? std::atol(argv[2]) : 300;
  const std::string law = argc > 3 ? argv[3] : "hertz";
  constexpr double kRadius = 1.5e-3;
  // A square bed 60 spheres high.
  const int nz = 60;
  const int nx = std::max(1, static_cast<int>(std::lround(std::sqrt(double(particles) / nz))));
  DemSettings s;
  s.material.particle = {kRadius, 390.0};
  s.material.particle_particle = testing::pine_table2_particle_particle();
  s.material.particle_wall = testing::pine_table2_particle_wall();
  s.law = law == "seed" ? choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "none")
                        : choose_contact_law("hertz", "mindlin", "cdt", "none");
  s.ranks = ranks;
  const double spacing = 2.0 * kRadius;
  const SimulationBox box{
      Vec3::Zero(), Vec3(nx * spacing, nx * spacing, (nz + 4) * spacing), {true, true, false}};
  ParticleStore p;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 jitter = 0.02 * kRadius * Vec3(u(rng), u(rng), 0.0);
        p.add(Vec3((i + 0.5) * spacing, (j + 0.5) * spacing, kRadius + k * spacing * 1.001) +
                  jitter,
              kRadius, 390.0, k);
      }
  DemEngine bed(s, box, std::move(p));
  bed.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  std::ostringstream plan;
  bed.prepare(plan);
  bed.run_steps(1500);
  const double before = bed.particle_steps();
  MPI_Barrier(MPI_COMM_WORLD);
  const auto start = std::chrono::steady_clock::now();
  bed.run_steps(steps);
  MPI_Barrier(MPI_COMM_WORLD);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double rate = (bed.particle_steps() - before) / seconds;
  const std::string balance = bed.rank_balance();
  const double ke = bed.kinetic_energy();
  const std::size_t count = bed.global_count();
  if (ranks.rank() == 0) {
    const int threads = omp_get_max_threads();
    std::cout << plan.str() << bed.performance_report() << balance;
    std::printf(
        "RESULT law %s particles %zu ranks %d threads %d steps %ld: %.4g s, %.4g "
        "particle-steps/s, %.4g per core; kinetic energy %.17g J\n",
        law.c_str(), count, ranks.size(), threads, steps, seconds, rate,
        rate / (ranks.size() * threads), ke);
  }
  MPI_Finalize();
  return 0;
}
