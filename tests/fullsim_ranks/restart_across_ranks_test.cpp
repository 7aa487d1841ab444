#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>

#include "fullsim/dem/dem_checkpoint.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;
namespace fs = std::filesystem;

// The bed of dem_on_ranks_test.cpp, smaller: 1 350 spheres dropped on a floor in a periodic
// box under tilted gravity, so grains slide across the cut and contacts carry history.
DemEngine dropped_bed(const DemRanks& ranks) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.1);
  s.ranks = ranks;
  s.gravity = Vec3(4.0, 0.0, -9.81);
  ParticleStore p;
  add_lattice(p, Vec3(0.0016, 0.0016, 0.0016), 15, 15, 6, 0.0032, 0.05);
  const SimulationBox box{Vec3::Zero(), Vec3(15 * 0.0032, 15 * 0.0032, 0.03), {true, true, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  return e;
}

// Every rank's own particles' positions by id.
std::vector<Vec3> positions_by_id(const DemEngine& e, std::size_t n, const DemRanks& ranks) {
  std::vector<double> mine;
  const ParticleStore& p = e.particles();
  for (std::size_t k = 0; k < e.owned_count(); ++k)
    mine.insert(mine.end(), {static_cast<double>(p.id[k]), p.position[k].x(), p.position[k].y(),
                             p.position[k].z()});
  std::vector<Vec3> x(n, Vec3::Constant(std::nan("")));
  for (const auto& from : ranks.all_gather(mine))
    for (std::size_t k = 0; k < from.size(); k += 4)
      x[static_cast<std::size_t>(from[k])] = Vec3(from[k + 1], from[k + 2], from[k + 3]);
  return x;
}

// Across the periodic faces, the nearest image (a run wraps positions at its list rebuilds, and
// a restarted one rebuilds at the restart).
double largest_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b,
                          const SimulationBox& box) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k)
    worst = std::max(worst, box.minimum_image(a[k] - b[k]).norm());
  return std::isnan(worst) ? 1.0 : worst;
}

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
  std::ostringstream plan;
  DemEngine shared = dropped_bed(ranks), alone = dropped_bed(DemRanks::one());
  shared.prepare(plan);
  alone.prepare(plan);
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
    DemSettings s = hertz_settings(0.3, 0.5, 0.1);
    s.ranks = c.on;
    s.gravity = Vec3(4.0, 0.0, -9.81);
    DemEngine restarted(s, read_dem_checkpoint(folder / c.file));
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

}  // namespace
}  // namespace feedflow
