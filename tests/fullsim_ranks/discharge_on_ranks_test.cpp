#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "tests/fullsim_ranks/ranks_test_bed.hpp"

namespace feedflow {
namespace {

using namespace ranks_test;

// The bed of ranks_test_bed.hpp on a floor that opens, over an outlet sink (the plane
// z = -3 mm): the bed falls through it and is removed grain by grain.
DemEngine opening_bed(const DemRanks& ranks) {
  ParticleStore p;
  add_lattice(p, Vec3(0.0016, 0.0016, 0.0016), 15, 15, 6, 0.0032, 0.05);
  const SimulationBox box{Vec3(0.0, 0.0, -0.01), Vec3(15 * 0.0032, 15 * 0.0032, 0.03),
                          {true, true, false}};
  DemEngine e(dropped_bed_settings(ranks), box, p);
  e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  e.set_outlet_sink(OutletSink::plane(Vec3(0.0, 0.0, -0.003), -Vec3::UnitZ()));
  std::ostringstream plan;
  e.prepare(plan);
  return e;
}

// The outlet sink on ranks: each rank removes the grains it owns as they cross, and the merged
// books are one rank's: the same grains at the same times (every event equal, in order), the
// same mass, at every stage of the discharge; the grains left are where one rank has them.
TEST(DischargeOnRanks, MergedSinkBooksAreOneRanks) {
  const DemRanks ranks = DemRanks::world();
  DemEngine shared = opening_bed(ranks), alone = opening_bed(DemRanks::one());
  shared.run_steps(300);
  alone.run_steps(300);
  for (DemEngine* e : {&shared, &alone}) e->set_wall_removal_time("floor", e->time());
  std::size_t stages = 0;
  for (int chunk = 0; chunk < 40; ++chunk) {
    shared.run_steps(100);
    alone.run_steps(100);
    const OutletSink a = *alone.merged_outlet_sink(), s = *shared.merged_outlet_sink();
    ASSERT_EQ(s.removed_count(), a.removed_count()) << "at step " << alone.step();
    for (std::size_t k = 0; k < a.events().size(); ++k) {
      ASSERT_EQ(s.events()[k].id, a.events()[k].id) << k;
      ASSERT_EQ(s.events()[k].time, a.events()[k].time) << k;
    }
    EXPECT_NEAR(s.removed_mass(), a.removed_mass(), 1e-12 * a.removed_mass());
    EXPECT_EQ(shared.global_count() + s.removed_count(), 1350u);
    stages += a.removed_count() > 0 && a.removed_count() < 1350;
  }
  const std::size_t removed = alone.merged_outlet_sink()->removed_count();
  const double worst = largest_difference(positions_by_id(shared, 1350, ranks),
                                          positions_by_id(alone, 1350, DemRanks::one()),
                                          alone.box());
  if (ranks.rank() == 0)
    std::printf("discharge on %d ranks: %zu of 1350 grains through the sink by step %ld, %zu "
                "stages mid-way, largest position difference of those left %.3g m\n",
                ranks.size(), removed, alone.step(), stages, worst);
  EXPECT_GT(stages, 3u);  // compared while the bed was passing the sink
  EXPECT_LT(worst, 1e-12);
}

}  // namespace
}  // namespace feedflow
