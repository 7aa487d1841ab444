#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <sstream>

#include "fullsim/dem/ranks/gathered_particles.hpp"
#include "fullsim/dem/scene/drum_angle_watch.hpp"
#include "fullsim/dem/scene/drum_scene.hpp"
#include "fullsim/dem/scene/wedge_hopper_slab.hpp"
#include "tests/fullsim_ranks/ranks_test_bed.hpp"
#include "tests/support/pine_table2.hpp"

namespace feedflow {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

DemSettings table2_settings(const DemRanks& ranks, double wall_friction) {
  DemSettings s;
  s.material.particle = {3e-3, 390.0};
  s.material.particle_particle = testing::pine_table2_particle_particle();
  s.material.particle_wall = testing::pine_table2_contact(wall_friction, 0.6);
  s.law = choose_contact_law("hertz", "mindlin", "cdt", "none");
  s.ranks = ranks;
  return s;
}

struct HopperRun {
  FillReport fill;
  std::size_t in_domain = 0, sunk = 0;
  double booked_mass = 0.0;  // in the domain + sunk + trimmed [kg]
  std::size_t distinct_ids = 0;  // in the domain, sunk (each once) and trimmed
};

// A small wedge slab (30 deg, 60 mm outlet, 0.12 m bin) of 3 mm spheres rain-filled, trimmed
// and discharged for 0.25 s, read as a scene reads it: the whole bed and the merged sink.
HopperRun fill_and_discharge(const DemRanks& ranks) {
  const WedgeHopperSlab h{30.0 * kDeg, 0.06, 0.12, 0.1, 6e-3, 3e-3, 0.3};
  DemEngine e(table2_settings(ranks, 0.2), h.box(), ParticleStore{});
  h.add_walls(e);
  std::ostringstream log;
  RainFillSettings rain = h.rain(390.0, 5, 7);
  rain.settle_time_cap = 0.1;
  HopperRun run;
  run.fill = rain_fill(e, rain, log);
  e.set_wall_removal_time("gate", e.time());
  e.advance_to(e.time() + 0.25);
  const ParticleStore bed = all_gather_particles(e.particles(), e.owned_count(), ranks);
  const OutletSink sink = *e.merged_outlet_sink();
  run.in_domain = bed.size();
  run.sunk = sink.removed_count();
  run.booked_mass = bed.total_mass() + sink.removed_mass() + run.fill.trimmed_mass;
  std::set<std::uint32_t> ids(bed.id.begin(), bed.id.end());
  for (const SinkEvent& ev : sink.events()) ids.insert(ev.id);
  run.distinct_ids = ids.size() + run.fill.trimmed_count;
  EXPECT_EQ(e.global_count(), bed.size());
  return run;
}

// The hopper's fill and discharge on ranks: every rank places the same spheres from the whole
// bed, trims the same ones and books them once; every rained-in sphere is in the domain, sunk
// or trimmed exactly once, the mass to round-off; the fill is one rank's and the discharge after
// 0.25 s within the spread of runs that differ by round-off (contacts amplify it).
TEST(HopperOnRanks, RainFilledSlabKeepsItsBooksAndDischargesLikeOneRank) {
  const DemRanks ranks = DemRanks::world();
  const HopperRun shared = fill_and_discharge(ranks), alone = fill_and_discharge(DemRanks::one());
  const FillReport& f = shared.fill;
  EXPECT_EQ(shared.in_domain + shared.sunk + f.trimmed_count, f.inserted_count);
  EXPECT_EQ(shared.distinct_ids, f.inserted_count);
  EXPECT_NEAR(shared.booked_mass, f.inserted_mass, 1e-13 * f.inserted_mass);
  EXPECT_EQ(f.inserted_count, alone.fill.inserted_count);
  if (ranks.rank() == 0)
    std::printf("hopper on %d ranks: %zu rained in (one rank %zu), %zu trimmed (%zu), %zu sunk "
                "in 0.25 s (%zu)\n",
                ranks.size(), f.inserted_count, alone.fill.inserted_count, f.trimmed_count,
                alone.fill.trimmed_count, shared.sunk, alone.sunk);
  ASSERT_GT(alone.sunk, 20u);  // it discharged
  EXPECT_NEAR(static_cast<double>(shared.sunk), static_cast<double>(alone.sunk),
              0.15 * static_cast<double>(alone.sunk));
}

struct DrumRun {
  FillReport fill;
  std::size_t particles = 0;
  double angle = 0.0, angle_sd = 0.0;  // [rad]
};

// The seed drum's slab twin (145 mm, 50 % fill, 18 mm slab) filled, turned at 10 rpm and its
// surface angle sampled each 0.02 s until steady, as a scene reads it.
DrumRun fill_and_turn(const DemRanks& ranks) {
  DrumSceneSpec spec;
  spec.slab_depth = 18e-3;
  spec.speed = 10.0 * 2.0 * std::numbers::pi / 60.0;
  DrumScene drum(table2_settings(ranks, std::tan(20 * kDeg)), spec);
  std::ostringstream log;
  DrumRun run;
  run.fill = drum.fill(log);
  drum.start_rotation(log);
  DrumAngleWatch watch(0.0725, 0.72, 0.3, 1.5 * kDeg);  // spin-up 0.12 of a turn
  while (!watch.converged() && watch.samples().size() < 100) {  // at most 2 s of rotation
    drum.engine().advance_to(drum.engine().time() + 0.02);
    watch.add(drum.sample());
  }
  run.particles = drum.engine().global_count();
  if (const auto steady = watch.steady()) {
    run.angle = steady->angle;
    run.angle_sd = steady->angle_sd;
  }
  return run;
}

// The drum on ranks: the same spheres rained in as on one rank, a bed of the same size after
// the trim, rebuilt from its gathered checkpoint on every rank to start turning, and its steady
// angle at 10 rpm within two of its standard deviations (and 2 deg) of one rank's.
TEST(DrumOnRanks, FilledAndTurnedLikeOneRank) {
  const DemRanks ranks = DemRanks::world();
  const DrumRun shared = fill_and_turn(ranks), alone = fill_and_turn(DemRanks::one());
  if (ranks.rank() == 0)
    std::printf("drum on %d ranks: %zu particles (one rank %zu), angle %.2f +- %.2f deg (%.2f +- "
                "%.2f)\n",
                ranks.size(), shared.particles, alone.particles, shared.angle / kDeg,
                shared.angle_sd / kDeg, alone.angle / kDeg, alone.angle_sd / kDeg);
  EXPECT_EQ(shared.fill.inserted_count, alone.fill.inserted_count);
  // The trim line cuts the top layer: a settled bed that differs by amplified round-off keeps a
  // few grains more or fewer (rain seeds 1-5 keep 745-760 on one rank, 745-760 on two).
  EXPECT_NEAR(static_cast<double>(shared.particles), static_cast<double>(alone.particles),
              0.02 * static_cast<double>(alone.particles));
  ASSERT_GT(alone.angle, 20 * kDeg);  // it turned and reached a steady angle
  EXPECT_NEAR(shared.angle, alone.angle, std::max(2.0 * kDeg, 2.0 * alone.angle_sd));
}

}  // namespace
}  // namespace feedflow
