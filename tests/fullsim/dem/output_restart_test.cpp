#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/dem/dem_checkpoint.hpp"
#include "fullsim/dem/particle_snapshots.hpp"
#include "models/os/interrupt_request.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;
namespace fs = std::filesystem;

fs::path output_scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("feedflow_demio_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// A settling block of 64 frictional, rolling-resisting spheres in a box whose floor slides
// sideways, with an outlet sink that takes one sphere at the first step; small skin and a
// Morton re-sort at every rebuild so the list is rebuilt and re-sorted in both halves.
DemSettings restart_settings() {
  DemSettings s = hertz_settings(0.5, 0.5, 0.1);
  s.skin_fraction = 0.05;
  s.sort_every = 1;
  return s;
}

DemEngine make_restart_scene(const DemSettings& s, const Vec3& origin = Vec3(2e-3, 2e-3, 1.6e-3),
                             int rows_in_y = 4) {
  ParticleStore p;
  add_lattice(p, origin, 4, rows_in_y, 4, 2.95e-3, 0.05);
  const Vec3 lower(0, 0, 0), upper(0.016, 0.016, 0.02);
  DemEngine e(s, SimulationBox{lower, upper, {false, false, false}}, p);
  e.add_wall(Wall::plane("floor", lower, Vec3::UnitZ()).moving(Vec3(0.02, 0, 0), Vec3::Zero()));
  add_side_walls(e, lower, upper);
  // Around the top corner sphere of the lattice (centre (2, 2, 1.6 + 3 x 2.95) mm).
  e.set_outlet_sink(OutletSink::box(Vec3(1.5e-3, 1.5e-3, 10e-3), Vec3(2.5e-3, 2.5e-3, 11e-3)));
  return e;
}

std::size_t nonzero_histories(const std::vector<double>& h) {
  std::size_t k = 0;
  for (double v : h) k += v != 0.0;
  return k;
}

// Restart bit-identity: N steps straight equal N/2 steps, a checkpoint written to disk, a
// fresh engine restored from it and N/2 more steps, bit for bit in every particle's position,
// velocity, angular velocity, the contact and wall histories, the walls and the sink; with
// particle-particle and particle-wall contacts carrying history at the checkpoint.
TEST(DemOutputRestart, RestartedRunContinuesBitIdentically) {
  const fs::path dir = output_scratch("restart");
  const DemSettings s = restart_settings();
  const long N = 600;
  std::ostringstream plan;

  DemEngine straight = make_restart_scene(s);
  straight.prepare(plan);
  straight.run_steps(N);

  DemEngine first = make_restart_scene(s);
  first.prepare(plan);
  first.run_steps(N / 2);
  const std::size_t pair_history = nonzero_histories(first.neighbours().history);
  const std::size_t wall_history = nonzero_histories(first.particles().wall_history);
  const std::size_t rebuilds_at_checkpoint = first.neighbours().rebuild_count();
  first.write_checkpoint(dir / "half.h5");

  DemEngine restored(s, read_dem_checkpoint(dir / "half.h5"));
  restored.prepare(plan);
  restored.run_steps(N - N / 2);
  std::printf("restart: %zu pair and %zu wall history doubles non-zero at the checkpoint; "
              "rebuilds %zu at the checkpoint, %zu at the end; %zu particles, %zu removed\n",
              pair_history, wall_history, rebuilds_at_checkpoint,
              restored.neighbours().rebuild_count(), restored.particles().size(),
              restored.outlet_sink()->removed_count());
  ASSERT_GT(pair_history, 0u) << "no particle-particle contact history at the checkpoint";
  ASSERT_GT(wall_history, 0u) << "no particle-wall contact history at the checkpoint";
  ASSERT_GT(restored.neighbours().rebuild_count(), rebuilds_at_checkpoint)
      << "the second half did not rebuild the list";
  ASSERT_EQ(restored.outlet_sink()->removed_count(), 1u);

  const ParticleStore& a = straight.particles();
  const ParticleStore& b = restored.particles();
  EXPECT_EQ(restored.step(), straight.step());
  const double t_restored = restored.time(), t_straight = straight.time();
  EXPECT_EQ(std::memcmp(&t_restored, &t_straight, sizeof(double)), 0);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.id, b.id);
  const std::size_t bytes = a.size() * sizeof(Vec3);
  EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(a.velocity.data(), b.velocity.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(a.angular_velocity.data(), b.angular_velocity.data(), bytes), 0);
  EXPECT_EQ(a.wall_history, b.wall_history);
  EXPECT_EQ(straight.neighbours().history, restored.neighbours().history);
  EXPECT_EQ(straight.neighbours().entry_keys(), restored.neighbours().entry_keys());
  EXPECT_EQ(straight.walls()[0].point(), restored.walls()[0].point());
  EXPECT_EQ(straight.outlet_sink()->removed_mass(), restored.outlet_sink()->removed_mass());
  fs::remove_all(dir);
}

// A plane hold (a one-layer slab's) set on the engine goes through restore(): the restored
// engine still holds, and its particles continue with the straight run's bits (the slab scenes
// restore into an engine built with their walls and hold).
TEST(DemOutputRestart, RestoreKeepsThePlaneHold) {
  const fs::path dir = output_scratch("hold");
  const DemSettings s = restart_settings();
  const long N = 400;
  std::ostringstream plan;
  auto held = [&s]() {  // one layer of 16 spheres in the plane y = 8 mm, on the sliding floor
    DemEngine e = make_restart_scene(s, Vec3(2e-3, 8e-3, 1.6e-3), 1);
    e.hold_in_plane(1);
    return e;
  };
  DemEngine straight = held();
  straight.prepare(plan);
  straight.run_steps(N);
  DemEngine first = held();
  first.prepare(plan);
  first.run_steps(N / 2);
  first.write_checkpoint(dir / "half.h5");
  DemEngine restored = held();
  restored.restore(Hdf5File(dir / "half.h5", Hdf5File::Mode::read));
  EXPECT_TRUE(restored.holds_in_plane());
  restored.prepare(plan);
  restored.run_steps(N - N / 2);
  const ParticleStore& a = straight.particles();
  const ParticleStore& b = restored.particles();
  ASSERT_EQ(a.size(), b.size());
  const std::size_t bytes = a.size() * sizeof(Vec3);
  EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(a.velocity.data(), b.velocity.data(), bytes), 0);
  for (std::size_t i = 0; i < b.size(); ++i) EXPECT_EQ(b.position[i].y(), 8e-3);
  fs::remove_all(dir);
}

// The blow-up guard's energy book (initial energy, floor, gravity work, the wall speed the floor
// allows for) goes through a restart as it was: a run whose floor slides from the start,
// checkpointed while one sphere thrown up at 0.5 m/s makes the bed ~10 mm taller than at the start
// (a floor re-taken from that bed would be higher), ends with the book of the uninterrupted run,
// bit for bit, and the same guard line in its plan.
TEST(DemOutputRestart, RestartKeepsTheGuardsEnergyBook) {
  const fs::path dir = output_scratch("guard_book");
  const DemSettings s = restart_settings();
  auto scene = [&s] {
    ParticleStore p;
    add_lattice(p, Vec3(2e-3, 2e-3, kRadius), 4, 4, 1, 2.95e-3, 0.0);  // one layer on the floor
    p.add(Vec3(8e-3, 8e-3, 6e-3), kRadius, kDensity, 1, Vec3(0.0, 0.0, 0.5));
    const Vec3 lower(0, 0, 0), upper(0.016, 0.016, 0.03);
    DemEngine e(s, SimulationBox{lower, upper, {false, false, false}}, p);
    e.add_wall(Wall::plane("floor", lower, Vec3::UnitZ()).moving(Vec3(0.02, 0, 0), Vec3::Zero()));
    add_side_walls(e, lower, upper);
    return e;
  };
  std::ostringstream plan;
  DemEngine straight = scene();
  straight.prepare(plan);
  // Halfway (0.04 s) the thrown sphere is near the top of its flight.
  const long N = 2 * std::lround(0.04 / straight.time_step());
  straight.run_steps(N);

  DemEngine first = scene();
  first.prepare(plan);
  first.run_steps(N / 2);
  double lowest = 1.0, highest = -1.0;
  for (const Vec3& x : first.particles().position) {
    lowest = std::min(lowest, x.z());
    highest = std::max(highest, x.z());
  }
  ASSERT_GT(highest - lowest, 5e-3) << "the bed at the checkpoint is not taller than at the start";
  first.write_checkpoint(dir / "half.h5");
  DemEngine restored(s, read_dem_checkpoint(dir / "half.h5"));
  std::ostringstream restored_plan;
  restored.prepare(restored_plan);
  restored.run_steps(N - N / 2);

  const DemCheckpoint a = straight.checkpoint(), b = restored.checkpoint();
  ASSERT_EQ(a.step, b.step);
  EXPECT_GT(a.guard_wall_speed, 0.0);
  auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v); };
  EXPECT_EQ(bits(b.guard_initial_energy), bits(a.guard_initial_energy));
  EXPECT_EQ(bits(b.guard_energy_floor), bits(a.guard_energy_floor))
      << b.guard_energy_floor << " J after the restart, " << a.guard_energy_floor << " J straight";
  EXPECT_EQ(bits(b.guard_gravity_work), bits(a.guard_gravity_work));
  EXPECT_EQ(bits(b.guard_wall_speed), bits(a.guard_wall_speed));
  auto guard_line = [](const std::string& text) {
    const std::string from = text.substr(text.find("blow-up guard"));
    return from.substr(0, from.find('\n'));
  };
  EXPECT_EQ(guard_line(restored.plan()), guard_line(straight.plan()));
  fs::remove_all(dir);
}

// Walls set moving after a checkpoint taken while they stood still (a drum started after its
// fill) raise the restored run's floor for them: the book then allows for the floor's 0.02 m/s,
// its floor is above the checkpoint's and the plan says so.
TEST(DemOutputRestart, WallsSetMovingSinceTheCheckpointRaiseTheFloor) {
  const DemSettings s = restart_settings();
  ParticleStore p;
  add_lattice(p, Vec3(2e-3, 2e-3, 1.6e-3), 4, 4, 4, 2.95e-3, 0.05);
  const Vec3 lower(0, 0, 0), upper(0.016, 0.016, 0.02);
  DemEngine still(s, SimulationBox{lower, upper, {false, false, false}}, p);
  add_box_walls(still, lower, upper);
  std::ostringstream plan;
  still.prepare(plan);
  still.run_steps(200);
  DemCheckpoint c = still.checkpoint();
  ASSERT_EQ(c.guard_wall_speed, 0.0);
  ASSERT_EQ(c.walls[4].name(), "z-");
  c.walls[4].moving(Vec3(0.02, 0, 0), Vec3::Zero());
  DemEngine moving(s, c);
  moving.prepare(plan);
  const DemCheckpoint m = moving.checkpoint();
  EXPECT_NEAR(m.guard_wall_speed, 0.02, 1e-15);
  EXPECT_GT(m.guard_energy_floor, c.guard_energy_floor);
  EXPECT_EQ(m.guard_gravity_work, c.guard_gravity_work);
  EXPECT_NE(moving.plan().find("moving walls up to 0.02 m/s"), std::string::npos) << moving.plan();
}

// A run that emptied (every sphere taken by the sink, as a drained hopper's last moments) and
// was checkpointed so continues: the restored engine, holding no particle, takes its grid and
// step from the material's spheres, the same step as the run's, and goes on in time.
TEST(DemOutputRestart, AnEmptiedRunRestarts) {
  const DemSettings s = restart_settings();
  DemEngine e = make_restart_scene(s);
  e.set_outlet_sink(OutletSink::box(Vec3(0, 0, 0), Vec3(0.016, 0.016, 0.02)));
  std::ostringstream plan;
  e.prepare(plan);
  e.run_steps(10);
  ASSERT_EQ(e.particles().size(), 0u);
  DemEngine restored(s, e.checkpoint());
  ASSERT_NO_THROW(restored.prepare(plan));
  EXPECT_EQ(restored.time_step(), e.time_step());
  restored.run_steps(10);
  EXPECT_EQ(restored.step(), 20);
}

// A damaged checkpoint is refused with the file named: cut to half its size, a future format
// version, and (at prepare) settings giving another time step than the checkpointed run's.
TEST(DemOutputRestart, TruncatedWrongVersionOrMismatchedCheckpointIsRefused) {
  const fs::path dir = output_scratch("refuse");
  const DemSettings s = restart_settings();
  DemEngine e = make_restart_scene(s);
  std::ostringstream plan;
  e.prepare(plan);
  e.run_steps(20);
  const fs::path good = dir / "good.h5";
  e.write_checkpoint(good);
  EXPECT_NO_THROW(read_dem_checkpoint(good));

  const fs::path cut = dir / "cut.h5";
  fs::copy_file(good, cut);
  fs::resize_file(cut, fs::file_size(good) / 2);
  try {
    read_dem_checkpoint(cut);
    ADD_FAILURE() << "a truncated checkpoint was read";
  } catch (const std::runtime_error& x) {
    EXPECT_NE(std::string(x.what()).find(cut.string()), std::string::npos) << x.what();
  }

  const fs::path future = dir / "future.h5";
  fs::copy_file(good, future);
  {
    const hid_t f = H5Fopen(future.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t a = H5Aopen(f, "format_version", H5P_DEFAULT);
    const std::int64_t v = kDemCheckpointVersion + 1;
    ASSERT_GE(H5Awrite(a, H5T_NATIVE_INT64, &v), 0);
    H5Aclose(a);
    H5Fclose(f);
  }
  try {
    read_dem_checkpoint(future);
    ADD_FAILURE() << "a checkpoint of another version was read";
  } catch (const std::runtime_error& x) {
    const std::string what = x.what();
    EXPECT_NE(what.find(future.string()), std::string::npos) << what;
    EXPECT_NE(what.find("format version " + std::to_string(kDemCheckpointVersion + 1)),
              std::string::npos)
        << what;
  }

  DemSettings other = s;
  other.requested_time_step = 0.5 * e.time_step();
  DemEngine mismatched(other, read_dem_checkpoint(good));
  EXPECT_THROW(mismatched.prepare(plan), std::runtime_error);
  fs::remove_all(dir);
}

// Snapshot read-back: the last snapshot written equals the engine's state bit for bit, the
// snapshots fall on the chosen interval, and their time and step are stored.
TEST(DemOutputRestart, SnapshotReadsBackTheStateWritten) {
  const fs::path dir = output_scratch("snapshot");
  DemEngine e = make_restart_scene(restart_settings());
  std::ostringstream plan;
  e.prepare(plan);
  ParticleSnapshots snapshots(dir / "particles.h5", 10);
  snapshots.write_if_due(e.particles(), e.time(), e.step());
  for (int k = 0; k < 35; ++k) {
    e.run_steps(1);
    snapshots.write_if_due(e.particles(), e.time(), e.step());
  }
  EXPECT_EQ(snapshots.count(), 4u);  // steps 0, 10, 20, 30
  e.run_steps(5);
  snapshots.write(e.particles(), e.time(), e.step());
  const ParticleSnapshot r =
      read_particle_snapshot(snapshots.hdf5_path(), ParticleSnapshots::group_name(e.step()));
  const ParticleStore& p = e.particles();
  EXPECT_EQ(r.step, 40);
  EXPECT_EQ(r.time, e.time());
  EXPECT_EQ(r.id, p.id);
  EXPECT_EQ(r.radius, p.radius);
  EXPECT_EQ(r.layer, p.layer);
  EXPECT_EQ(r.position, p.position);
  EXPECT_EQ(r.velocity, p.velocity);
  EXPECT_EQ(r.angular_velocity, p.angular_velocity);
  fs::remove_all(dir);
}

// The XDMF sidecar is a well-formed temporal collection of Polyvertex grids, one per snapshot
// with increasing times, and every dataset it names exists in the HDF5 file with the number of
// points its grid declares (opened with the HDF5 C API).
TEST(DemOutputRestart, XdmfSidecarNamesExistingDatasets) {
  const fs::path dir = output_scratch("xdmf");
  DemEngine e = make_restart_scene(restart_settings());
  std::ostringstream plan;
  e.prepare(plan);
  ParticleSnapshots snapshots(dir / "particles.h5", 5);
  for (int k = 0; k <= 15; ++k) {
    snapshots.write_if_due(e.particles(), e.time(), e.step());
    e.run_steps(1);
  }
  ASSERT_EQ(snapshots.count(), 4u);
  std::ifstream in(snapshots.xdmf_path());
  std::stringstream text;
  text << in.rdbuf();
  const std::string x = text.str();
  auto count = [&](const std::string& s) {
    std::size_t k = 0;
    for (auto p = x.find(s); p != std::string::npos; p = x.find(s, p + 1)) ++k;
    return k;
  };
  EXPECT_EQ(x.rfind("<?xml", 0), 0u);
  EXPECT_EQ(count("<Xdmf "), 1u);
  EXPECT_EQ(count("</Xdmf>"), 1u);
  EXPECT_EQ(count("<Domain>"), 1u);
  EXPECT_EQ(count("</Domain>"), 1u);
  EXPECT_EQ(count("CollectionType=\"Temporal\""), 1u);
  EXPECT_EQ(count("<Grid "), 5u);  // the collection and four snapshots
  EXPECT_EQ(count("</Grid>"), 5u);
  EXPECT_EQ(count("TopologyType=\"Polyvertex\""), 4u);
  EXPECT_EQ(count("GeometryType=\"XYZ\""), 4u);
  EXPECT_EQ(count("<DataItem "), count("</DataItem>"));
  EXPECT_EQ(count("<Attribute "), count("</Attribute>"));

  // Each grid: its time, its point count, and the datasets of its DataItems.
  const std::regex grid(R"re(<Time Value="([^"]+)"/>\s*<Topology TopologyType="Polyvertex" NumberOfElements="(\d+)")re");
  std::vector<double> times;
  std::vector<std::size_t> points;
  for (std::sregex_iterator it(x.begin(), x.end(), grid), end; it != end; ++it) {
    times.push_back(std::stod((*it)[1]));
    points.push_back(std::stoul((*it)[2]));
  }
  ASSERT_EQ(times.size(), 4u);
  for (std::size_t k = 1; k < times.size(); ++k) EXPECT_GT(times[k], times[k - 1]);

  const std::regex item(R"re(<DataItem Dimensions="(\d+)( 3)?"[^>]*Format="HDF">([^:<]+):([^<]+)</DataItem>)re");
  const hid_t f = H5Fopen(snapshots.hdf5_path().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  std::size_t items = 0;
  for (std::sregex_iterator it(x.begin(), x.end(), item), end; it != end; ++it) {
    ++items;
    const std::string file = (*it)[3], dataset = (*it)[4];
    EXPECT_EQ(file, "particles.h5");
    const hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
    ASSERT_GE(d, 0) << "the sidecar names a missing dataset " << dataset;
    const hid_t space = H5Dget_space(d);
    hsize_t dims[2] = {0, 0};
    const int rank = H5Sget_simple_extent_dims(space, dims, nullptr);
    EXPECT_EQ(rank, (*it)[2].matched ? 2 : 1) << dataset;
    EXPECT_EQ(dims[0], std::stoul((*it)[1])) << dataset;
    EXPECT_EQ(std::count(points.begin(), points.end(), dims[0]) > 0, true) << dataset;
    H5Sclose(space);
    H5Dclose(d);
  }
  H5Fclose(f);
  EXPECT_EQ(items, 4u * 6u);  // geometry and five attributes per snapshot
  fs::remove_all(dir);
}

}  // namespace
}  // namespace feedflow
