#include <gtest/gtest.h>

#include <omp.h>

#include <sstream>

#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

std::vector<Vec3> run_pile(int threads) {
  omp_set_num_threads(threads);
  DemSettings s = hertz_settings(0.3, 0.5, 0.1);
  s.parallel_from = 0;  // thread even this small pile
  ParticleStore p;
  add_lattice(p, Vec3(0.00149, 0.00149, 0.0016), 6, 6, 6, 0.00298, 0.05);  // touching
  SimulationBox box{Vec3::Zero(), Vec3(6 * 0.00298, 6 * 0.00298, 0.03), {true, true, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  std::ostringstream plan;
  e.prepare(plan);
  e.run_steps(200);
  const ParticleStore& q = e.particles();
  std::vector<Vec3> out(2 * q.size());
  std::size_t touching = 0;
  for (std::size_t i = 0; i < q.size(); ++i)
    for (std::size_t j = i + 1; j < q.size(); ++j)
      touching += (e.box().minimum_image(q.position[i] - q.position[j]).norm() < 2 * kRadius);
  EXPECT_GT(touching, 300u);  // a dense pile: the force sums mix both threads' rows
  for (std::size_t i = 0; i < q.size(); ++i) {
    out[q.id[i]] = q.position[i];
    out[q.size() + q.id[i]] = q.angular_velocity[i];
  }
  return out;
}

// 1 and 2 OpenMP threads give the same pile (216 touching spheres, 200 steps) to
// round-off: the per-thread force buffers change only the order of the sums.
TEST(DemThreads, OneAndTwoThreadsAgreeToRoundOff) {
  const int saved = omp_get_max_threads();
  const auto one = run_pile(1);
  const auto two = run_pile(2);
  const auto again = run_pile(2);
  omp_set_num_threads(saved);
  double worst = 0.0;
  for (std::size_t k = 0; k < one.size() / 2; ++k)
    worst = std::max(worst, (one[k] - two[k]).norm());
  std::printf("threads: largest position difference 1 vs 2 threads %.3g m\n", worst);
  EXPECT_LT(worst, 1e-9);
  EXPECT_EQ(two, again);  // bit-identical for a given thread count
}

}  // namespace
}  // namespace feedflow
