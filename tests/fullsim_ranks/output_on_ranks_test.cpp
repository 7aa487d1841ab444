#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "fullsim/dem/dem_checkpoint.hpp"
#include "fullsim/dem/particle_snapshots.hpp"
#include "tests/fullsim_ranks/ranks_test_bed.hpp"

namespace feedflow {
namespace {

using namespace ranks_test;
namespace fs = std::filesystem;

// A folder every rank names alike (the first rank's process id).
fs::path shared_folder(const DemRanks& ranks) {
  const double pid = ranks.max(ranks.rank() == 0 ? static_cast<double>(::getpid()) : 0.0);
  const fs::path folder =
      fs::temp_directory_path() / ("feedflow_restart_" + std::to_string(static_cast<long>(pid)));
  if (ranks.rank() == 0) fs::create_directories(folder);
  ranks.sum(0.0);  // the folder exists before anyone writes into it
  return folder;
}

// A checkpoint written on the ranks of the run (2 under mpirun) restarts on one rank and on as
// many ranks as it was written on, and a one-rank checkpoint restarts on the ranks: each
// continued run ends where the uninterrupted one does, to round-off (1e-12 m; the
// contacts' history, the forces and the energy book carried over), with the same kinetic energy.
TEST(RestartAcrossRanks, CheckpointOfNRanksContinuesOnMRanks) {
  const DemRanks ranks = DemRanks::world();
  const fs::path folder = shared_folder(ranks);
  DemEngine shared = prepared_bed(ranks), alone = prepared_bed(DemRanks::one());
  const long before = 900, after = 600;
  shared.run_steps(before);
  alone.run_steps(before);
  shared.write_checkpoint(folder / "shared.h5");  // collective: the first rank writes
  if (ranks.rank() == 0) alone.write_checkpoint(folder / "alone.h5");
  ranks.sum(0.0);
  shared.run_steps(after);
  alone.run_steps(after);
  const std::size_t n = alone.particles().size();
  const std::vector<Vec3> reference = positions_by_id(alone, n, DemRanks::one());
  const double energy = alone.kinetic_energy();
  ASSERT_GT(energy, 0.0);
  // Shared and alone agree before any restart (the test's baseline).
  EXPECT_LT(largest_difference(positions_by_id(shared, n, ranks), reference, alone.box()), 1e-12);

  struct Case {
    const char* name;
    const char* file;
    DemRanks on;
  };
  for (const Case& c : {Case{"ranks -> 1", "shared.h5", DemRanks::one()},
                        Case{"ranks -> ranks", "shared.h5", ranks},
                        Case{"1 -> ranks", "alone.h5", ranks}}) {
    DemEngine restarted(dropped_bed_settings(c.on), read_dem_checkpoint(folder / c.file));
    std::ostringstream plan;
    restarted.prepare(plan);
    EXPECT_EQ(restarted.global_count(), n) << c.name;
    EXPECT_EQ(restarted.step(), before) << c.name;
    restarted.run_steps(after);
    const double worst = largest_difference(positions_by_id(restarted, n, c.on), reference,
                                           alone.box());
    const double e = restarted.kinetic_energy();
    if (ranks.rank() == 0)
      std::printf("restart %s (%d ranks wrote, %d continue): largest position difference %.3g m, "
                  "KE %.6g / %.6g J\n",
                  c.name, c.file[0] == 's' ? ranks.size() : 1, c.on.size(), worst, e, energy);
    EXPECT_LT(worst, 1e-12) << c.name;
    EXPECT_NEAR(e, energy, 1e-9 * energy) << c.name;
  }
  ranks.sum(0.0);
  if (ranks.rank() == 0) fs::remove_all(folder);
}

// A snapshot of a run shared among ranks holds every particle once, as one rank's run has it
// (positions and velocities by id to round-off); every rank counts it; a snapshot the first
// rank cannot write stops every rank with its reason, none left waiting.
TEST(SnapshotOnRanks, FirstRankWritesEveryParticle) {
  const DemRanks ranks = DemRanks::world();
  const fs::path folder = shared_folder(ranks);
  DemEngine shared = prepared_bed(ranks), alone = prepared_bed(DemRanks::one());
  shared.run_steps(700);
  alone.run_steps(700);
  auto writer = shared.snapshot_writer(folder, false);
  writer->write();
  writer->write();  // the same step: not again
  EXPECT_EQ(writer->count(), 1u);
  ranks.sum(0.0);
  const std::size_t n = alone.particles().size();
  if (ranks.rank() == 0) {
    const ParticleSnapshot snap =
        read_particle_snapshot(folder / "particles.h5", ParticleSnapshots::group_name(700));
    ASSERT_EQ(snap.id.size(), n);
    std::vector<int> seen(n, 0);
    std::vector<Vec3> x(n), v(n);
    for (std::size_t k = 0; k < n; ++k) {
      ASSERT_LT(snap.id[k], n);
      ++seen[snap.id[k]];
      x[snap.id[k]] = snap.position[k];
      v[snap.id[k]] = snap.velocity[k];
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(n));  // each once
    const ParticleStore& a = alone.particles();
    double dx = 0.0, dv = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      dx = std::max(dx, alone.box().minimum_image(x[a.id[k]] - a.position[k]).norm());
      dv = std::max(dv, (v[a.id[k]] - a.velocity[k]).norm());
    }
    std::printf("snapshot on %d ranks: %zu particles, largest position difference %.3g m, "
                "velocity %.3g m/s\n", ranks.size(), n, dx, dv);
    EXPECT_LT(dx, 1e-12);
    EXPECT_LT(dv, 1e-9);
    EXPECT_TRUE(fs::exists(folder / "particles.xdmf"));
  }
  auto nowhere = shared.snapshot_writer(folder / "particles.h5", false);  // a file, not a folder
  EXPECT_THROW(nowhere->write(), std::runtime_error);
  ranks.sum(0.0);
  if (ranks.rank() == 0) fs::remove_all(folder);
}

}  // namespace
}  // namespace feedflow
