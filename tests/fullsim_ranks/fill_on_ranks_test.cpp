#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "tests/fullsim_ranks/ranks_test_bed.hpp"

namespace feedflow {
namespace {

using namespace ranks_test;

// Rains `count` spheres on the bed, a 10 x 10 layer at height z, moving down at 0.3 m/s: every
// rank makes the same calls (the engine's contract on ranks).
void rain_layer(DemEngine& e, double z, int count) {
  for (int k = 0; k < count; ++k) {
    const Vec3 x(0.0024 + 0.0046 * (k % 10), 0.0024 + 0.0046 * (k / 10 % 10), z);
    e.insert_particle(x, 0.0015, 500.0, 1.0, Vec3(0.0, 0.0, -0.3));
  }
}

// Flags the own particles above `z` (the trim of a fill to its line).
void trim_above(DemEngine& e, double z) {
  const ParticleStore& p = e.particles();
  std::vector<char> flagged(p.size(), 0);
  for (std::size_t k = 0; k < p.size(); ++k) flagged[k] = p.position[k].z() > z;
  e.remove_particles(flagged);
}

// Rain-fall insertion and trimming on a run shared among ranks: every rank inserts the same
// spheres and its owner keeps each, ids stay alike, and removal takes each flagged grain once;
// the run goes on as one rank's does (positions by id to round-off, the same grains left, the
// same kinetic energy; the guard's book takes the inserted energy on every rank, or it stops).
TEST(FillOnRanks, InsertedAndTrimmedBedMatchesOneRank) {
  const DemRanks ranks = DemRanks::world();
  DemEngine shared = prepared_bed(ranks), alone = prepared_bed(DemRanks::one());
  for (DemEngine* e : {&shared, &alone}) {
    e->run_steps(300);
    rain_layer(*e, 0.0215, 100);  // lands on the bed
    e->run_steps(500);
    trim_above(*e, 0.0190);  // takes some of the rain, leaves what landed deepest
    rain_layer(*e, 0.024, 100);  // ids go on after the removal
    e->run_steps(200);
  }
  const std::size_t ids = alone.particles().next_id();
  EXPECT_EQ(ids, 1350u + 200u);
  EXPECT_EQ(shared.particles().next_id(), ids);
  const std::size_t left = alone.particles().size();
  EXPECT_LT(left, 1350u + 200u);  // the trim took grains
  EXPECT_GT(left, 1200u);
  EXPECT_EQ(shared.global_count(), left);
  const double worst = largest_difference(positions_by_id(shared, ids, ranks),
                                          positions_by_id(alone, ids, DemRanks::one()),
                                          alone.box());
  const double e1 = alone.kinetic_energy(), e2 = shared.kinetic_energy();
  std::size_t rain_kept = 0;  // the first rain landed: some of it is under the trim line
  for (std::uint32_t id : alone.particles().id) rain_kept += id >= 1350 && id < 1450;
  EXPECT_GT(rain_kept, 0u);
  EXPECT_LT(rain_kept, 100u);
  if (ranks.rank() == 0)
    std::printf("fill on %d ranks: %zu of %zu grains left after the trim (%zu of the first rain), "
                "largest position difference %.3g m, KE %.6g / %.6g J\n",
                ranks.size(), left, ids, rain_kept, worst, e2, e1);
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(e2, e1, 1e-9 * e1);
}

}  // namespace
}  // namespace feedflow
