// `feedflow simulate --solver dem` on the drum and inclined-plane cases, as a user runs it, on
// reduced twins set from the command line (coarse particles R = 3 mm, Hertz normal law, 18 mm slab)
// so each run takes seconds: exit 0, results.json with rung L3 results, timeseries.csv and the
// checkpoint written, the reduced-model values beside the DEM ones.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "fullsim/dem/dem_checkpoint.hpp"
#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

class SimulateDem : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_folder("feedflow_simdem", true);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The same bytes in two arrays (doubles compared bit for bit, not by value).
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Two DEM checkpoints hold the same state to the last bit in every group: /run, /box, /particles,
// /neighbours, /walls, /outlet_sink and the blow-up guard's energy book in /guard.
void expect_same_checkpoint(const fs::path& straight, const fs::path& restarted) {
  const feedflow::DemCheckpoint a = feedflow::read_dem_checkpoint(straight);
  const feedflow::DemCheckpoint b = feedflow::read_dem_checkpoint(restarted);
  EXPECT_EQ(a.step, b.step);
  EXPECT_TRUE(same_bits(a.time, b.time) && same_bits(a.time_step, b.time_step) &&
              same_bits(a.particle_steps, b.particle_steps) && a.contact_law == b.contact_law &&
              a.gravity == b.gravity)
      << "/run";
  EXPECT_TRUE(a.box.lower == b.box.lower && a.box.upper == b.box.upper &&
              a.box.periodic == b.box.periodic)
      << "/box";
  const auto &p = a.particles, &q = b.particles;
  EXPECT_TRUE(same_bits(p.position, q.position) && same_bits(p.velocity, q.velocity) &&
              same_bits(p.angular_velocity, q.angular_velocity) && same_bits(p.force, q.force) &&
              same_bits(p.torque, q.torque) && same_bits(p.radius, q.radius) &&
              same_bits(p.mass, q.mass) && same_bits(p.inertia, q.inertia) &&
              same_bits(p.layer, q.layer) && p.id == q.id &&
              same_bits(p.wall_history, q.wall_history) && p.next_id() == q.next_id())
      << "/particles";
  const auto &l = a.neighbours, &m = b.neighbours;
  EXPECT_TRUE(l.first == m.first && l.partner == m.partner && l.entry_keys() == m.entry_keys() &&
              same_bits(l.history, m.history) &&
              same_bits(l.reference_positions(), m.reference_positions()) &&
              l.rebuild_count() == m.rebuild_count() && same_bits(l.skin(), m.skin()))
      << "/neighbours";
  ASSERT_EQ(a.walls.size(), b.walls.size());
  for (std::size_t k = 0; k < a.walls.size(); ++k) {
    EXPECT_TRUE(a.walls[k].point() == b.walls[k].point() &&
                a.walls[k].velocity() == b.walls[k].velocity() &&
                a.walls[k].angular_velocity() == b.walls[k].angular_velocity() &&
                same_bits(a.walls[k].removal_time(), b.walls[k].removal_time()))
        << "/walls/" << k;
  }
  ASSERT_EQ(a.sink.has_value(), b.sink.has_value());
  if (a.sink) {
    EXPECT_TRUE(same_bits(a.sink->removed_mass(), b.sink->removed_mass())) << "/outlet_sink";
  }
  EXPECT_TRUE(same_bits(a.guard_initial_energy, b.guard_initial_energy)) << "/guard initial_energy";
  EXPECT_TRUE(same_bits(a.guard_energy_floor, b.guard_energy_floor))
      << "/guard energy_floor: " << a.guard_energy_floor << " J straight, " << b.guard_energy_floor
      << " J restarted";
  EXPECT_TRUE(same_bits(a.guard_gravity_work, b.guard_gravity_work)) << "/guard gravity_work";
  EXPECT_TRUE(same_bits(a.guard_wall_speed, b.guard_wall_speed)) << "/guard wall_speed";
}

// The times of the snapshots an XDMF sidecar lists (what ParaView shows) [s].
std::vector<double> xdmf_times(const fs::path& sidecar) {
  const std::string text = slurp(sidecar);
  const std::regex time(R"re(<Time Value="([^"]+)"/>)re");
  std::vector<double> times;
  for (std::sregex_iterator it(text.begin(), text.end(), time), end; it != end; ++it)
    times.push_back(std::stod((*it)[1]));
  return times;
}

// One column of a timeseries.csv, found by its header ("time [s]"); empty when there is none.
std::vector<double> csv_column(const fs::path& csv, const std::string& header) {
  auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
    return out;
  };
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);
  const auto names = cells(line);
  const auto column =
      static_cast<std::size_t>(std::find(names.begin(), names.end(), header) - names.begin());
  std::vector<double> values;
  while (column < names.size() && std::getline(in, line))
    values.push_back(std::stod(cells(line).at(column)));
  return values;
}

// The sidecar of a restarted run's snapshots (particles_from_step_<step>.xdmf) in `folder`.
fs::path continued_sidecar(const fs::path& folder) {
  for (const auto& f : fs::directory_iterator(folder))
    if (f.path().filename().string().starts_with("particles_from_step_") &&
        f.path().extension() == ".xdmf")
      return f.path();
  return {};
}

const char* kTwin =
    " --set dem.slab_depth=18mm --set dem.normal_law=hertz --set material.dem.particle.radius=3mm";

// The seed drum at 20 rpm for 1.2 s of rotation: the DEM angle and regime come with rung L3
// (the angle with a band around it), beside the reduced model's (feedflow design) values; the
// time series has the angle column.
TEST_F(SimulateDem, DrumWritesRungL3AngleAndRegime) {
  const auto r = run_feedflow(std::string("simulate cases/rotating_drum_20rpm.toml --solver dem --time 1.2s") +
                                  kTwin + " --out run",
                              dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(slurp(dir_ / "run/results.json"));
  const auto& results = json.at("results");
  EXPECT_EQ(results.at("regime").at("rung"), "L3");
  EXPECT_NE(results.at("regime").at("value"), "not measured");
  const auto& angle = results.at("dynamic_angle_of_repose");
  EXPECT_EQ(angle.at("rung"), "L3");
  EXPECT_EQ(angle.at("unit"), "deg");
  const double a = angle.at("value").get<double>();
  EXPECT_GT(a, 20.0);
  EXPECT_LT(a, 70.0);
  EXPECT_LE(angle.at("low").get<double>(), a);
  EXPECT_GE(angle.at("high").get<double>(), a);
  EXPECT_EQ(results.at("dynamic_angle_of_repose_reduced_model").at("rung"), "L0");
  EXPECT_NE(slurp(dir_ / "run/timeseries.csv").find("dynamic_angle_of_repose [deg]"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "run/checkpoint.h5"));
  // The DEM block's phases cover the fill too (the engine rebuilt to turn keeps them): they
  // account for more than 80 % of the wall time (without the fill's, about 60 %: the fill is
  // 40 % of this run) and not more than it.
  const auto& block = json.at("performance").at(0);
  double phases = 0.0;
  for (const auto& [phase, seconds] : block.at("phases_s").items()) phases += seconds.get<double>();
  EXPECT_GT(phases, 0.8 * block.at("wall_s").get<double>());
  EXPECT_LE(phases, block.at("wall_s").get<double>());
}

// Without a [dem] snapshot_interval the drum writes particle snapshots (20-50 over the run; every
// 20 ms row for 0.4 s), and they share the time series' axis: each snapshot's time in
// particles.xdmf is the time of a row of timeseries.csv (the same step), the first at the first
// row (the shell's start), the last at the checkpoint's time; the time column is the simulation
// time (the start after the fill, not 0), time_after_start counts from the start.
TEST_F(SimulateDem, DrumSnapshotsAndSeriesShareOneTimeAxis) {
  const auto r = run_feedflow(
      std::string("simulate cases/rotating_drum_20rpm.toml --solver dem -q --time 0.4s") + kTwin +
          " --out run",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(fs::exists(dir_ / "run/particles.h5"));
  const std::vector<double> snapshots = xdmf_times(dir_ / "run/particles.xdmf");
  const std::vector<double> time = csv_column(dir_ / "run/timeseries.csv", "time [s]");
  const std::vector<double> after = csv_column(dir_ / "run/timeseries.csv", "time_after_start [s]");
  ASSERT_EQ(time.size(), 21u);
  ASSERT_EQ(after.size(), time.size());
  EXPECT_EQ(snapshots.size(), 21u);
  for (const double t : snapshots)
    EXPECT_NE(std::find(time.begin(), time.end(), t), time.end())
        << "snapshot at " << t << " s is on no row";
  ASSERT_FALSE(snapshots.empty());
  EXPECT_EQ(snapshots.front(), time.front());
  EXPECT_EQ(snapshots.back(), feedflow::read_dem_checkpoint(dir_ / "run/checkpoint.h5").time);
  EXPECT_GT(time.front(), 0.1);  // the fill took simulated time before the shell started
  EXPECT_EQ(after.front(), 0.0);
  for (std::size_t k = 0; k < time.size(); ++k)
    EXPECT_NEAR(time[k] - after[k], time.front(), 1e-9) << "row " << k;
}

// Restart: a drum run stopped at 0.4 s of rotation and continued from its checkpoint to 0.8 s
// writes the same time series, to the last digit, as an uninterrupted 0.8 s run (the angle, the
// bed state and the kinetic energy at every sample), ends with the same checkpoint, bit for bit,
// including the blow-up guard's energy floor (which the turning bed, taller at the restart than
// when the shell started, must not move), and writes the same particle snapshots after 0.4 s.
TEST_F(SimulateDem, DrumRestartContinuesTheSameSeries) {
  const std::string run = std::string("simulate cases/rotating_drum_20rpm.toml --solver dem -q") + kTwin;
  ASSERT_EQ(run_feedflow(run + " --time 0.8s --out whole", dir_).exit_code, 0);
  ASSERT_EQ(run_feedflow(run + " --time 0.4s --out first", dir_).exit_code, 0);
  const auto r = run_feedflow(run + " --time 0.8s --restart first/checkpoint.h5 --out second", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string whole = slurp(dir_ / "whole/timeseries.csv");
  EXPECT_GT(std::count(whole.begin(), whole.end(), '\n'), 30);
  EXPECT_EQ(slurp(dir_ / "second/timeseries.csv"), whole);
  expect_same_checkpoint(dir_ / "whole/checkpoint.h5", dir_ / "second/checkpoint.h5");
  // The continued run's snapshots (written by default) are the uninterrupted run's after 0.4 s.
  const std::vector<double> straight = xdmf_times(dir_ / "whole/particles.xdmf");
  const std::vector<double> continued = xdmf_times(continued_sidecar(dir_ / "second"));
  ASSERT_FALSE(continued.empty());
  ASSERT_GT(straight.size(), continued.size());
  EXPECT_EQ(continued,
            std::vector<double>(straight.end() - static_cast<std::ptrdiff_t>(continued.size()),
                                straight.end()));
}

// Restart on the inclined plane: a small plane (~700 rain-filled spheres, 100 x 80 mm fill, 50 mm
// gate) stopped 0.15 s after the release and continued from its checkpoint to 0.3 s writes the same
// time series, to the last digit, as an uninterrupted 0.3 s run, while the material is still
// running down the ramp (the front moves), so the contact history in the checkpoint is exercised;
// the checkpoints at 0.3 s are the same to the last bit.
TEST_F(SimulateDem, PlaneRestartContinuesTheSameSeries) {
  const std::string run = std::string("simulate cases/inclined_plane_29_5.toml --solver dem -q") + kTwin +
                          " --set chute.bin_length=100mm --set chute.bin_height=0.16m --set chute.fill_height=80mm"
                          " --set chute.length=0.4m --set chute.gate_opening=50mm";
  ASSERT_EQ(run_feedflow(run + " --time 0.3s --out whole", dir_).exit_code, 0);
  ASSERT_EQ(run_feedflow(run + " --time 0.15s --out first", dir_).exit_code, 0);
  const auto r = run_feedflow(run + " --time 0.3s --restart first/checkpoint.h5 --out second", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string whole = slurp(dir_ / "whole/timeseries.csv");
  EXPECT_GT(std::count(whole.begin(), whole.end(), '\n'), 14);
  EXPECT_EQ(slurp(dir_ / "second/timeseries.csv"), whole);
  expect_same_checkpoint(dir_ / "whole/checkpoint.h5", dir_ / "second/checkpoint.h5");
  // The flow was still running at the restart: the front advanced after 0.15 s.
  const auto json = nlohmann::json::parse(slurp(dir_ / "first/results.json"));
  const auto json2 = nlohmann::json::parse(slurp(dir_ / "second/results.json"));
  EXPECT_GT(json2.at("results").at("deposit_front").at("value").get<double>(),
            json.at("results").at("deposit_front").at("value").get<double>());
}

// A time step above the stable one (here 40 us against the twin's 32 us) is refused as bad input
// naming dem.time_step and the stable step; with force_time_step = yes it is taken and the
// plan says so.
TEST_F(SimulateDem, StepAboveTheStableOneOnlyWhenForced) {
  const std::string run = std::string("simulate cases/rotating_drum_20rpm.toml --solver dem -q") +
                          kTwin + " --set dem.time_step=40us --time 0.02s";
  const auto refused = run_feedflow(run + " --out refused", dir_);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("dem.time_step"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("exceeds the stable step 3.201e-05 s"), std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(dir_ / "refused" / "results.json"));
  const auto forced = run_feedflow(run + " --set dem.force_time_step=yes --out forced", dir_);
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_NE(slurp(dir_ / "forced" / "results.json")
                .find("user step 4e-05 s FORCED above the stable step"),
            std::string::npos);
}

// A checkpoint continues only the case it was written for: a restart with another drum
// diameter, speed or slab depth is refused as bad input (exit 2) naming the key and both values,
// and writes nothing.
TEST_F(SimulateDem, RestartOfAnotherCaseIsRefused) {
  const std::string run = std::string("simulate cases/rotating_drum_20rpm.toml --solver dem -q") + kTwin;
  ASSERT_EQ(run_feedflow(run + " --time 0.05s --out first", dir_).exit_code, 0);
  for (const auto& [set, key, was] : {std::tuple{"drum.diameter=100mm", "drum.diameter", "145 mm"},
                                      std::tuple{"drum.speed=10rpm", "drum.speed", "20 rpm"},
                                      std::tuple{"dem.slab_depth=20mm", "dem.slab_depth", "18 mm"}}) {
    const auto r = run_feedflow(run + " --set " + set + " --time 0.1s --restart first/checkpoint.h5 --out second", dir_);
    EXPECT_EQ(r.exit_code, 2) << set;
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(was), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "second" / "results.json"));
  }
}

// A damaged checkpoint is never restarted silently: 8 kB zeroed anywhere in it either stops the
// restart as bad input naming --restart (exit 2, nothing written) or touched no byte the run
// reads (the same series as the undamaged restart); a file that is not a checkpoint is refused.
TEST_F(SimulateDem, DamagedOrForeignCheckpointIsRefused) {
  const std::string run = std::string("simulate cases/rotating_drum_20rpm.toml --solver dem -q") + kTwin +
                          " --set dem.snapshot_interval=0.05s";
  ASSERT_EQ(run_feedflow(run + " --time 0.05s --out first", dir_).exit_code, 0);
  const std::string good = slurp(dir_ / "first" / "checkpoint.h5");
  ASSERT_EQ(run_feedflow(run + " --time 0.06s --restart first/checkpoint.h5 --out clean", dir_).exit_code, 0);
  const std::string clean = slurp(dir_ / "clean" / "timeseries.csv");
  int refused = 0;
  for (int k = 0; k < 8; ++k) {
    std::string damaged = good;
    const std::size_t at = damaged.size() * k / 8;
    std::fill_n(damaged.begin() + at, std::min<std::size_t>(8192, damaged.size() - at), '\0');
    std::ofstream(dir_ / "damaged.h5", std::ios::binary) << damaged;
    fs::remove_all(dir_ / "second");
    const auto r = run_feedflow(run + " --time 0.06s --restart damaged.h5 --out second", dir_);
    if (r.exit_code == 2) {
      ++refused;
      EXPECT_NE(r.err.find("--restart"), std::string::npos) << r.err;
      EXPECT_FALSE(fs::exists(dir_ / "second" / "results.json")) << "offset " << at;
    } else {
      ASSERT_EQ(r.exit_code, 0) << "offset " << at << ": " << r.err;
      EXPECT_EQ(slurp(dir_ / "second" / "timeseries.csv"), clean) << "offset " << at << " changed the run silently";
    }
  }
  EXPECT_GE(refused, 4);  // most of the file is checksummed particle and contact data
  for (const char* foreign : {"first/particles.h5", "first/results.json"}) {
    const auto r = run_feedflow(run + " --time 0.06s --restart " + std::string(foreign) + " --out third", dir_);
    EXPECT_EQ(r.exit_code, 2) << foreign << ": " << r.err;
    EXPECT_NE(r.err.find("--restart"), std::string::npos) << r.err;
  }
}

// A slab thinner than two neighbour cutoffs is refused naming the key (exit 2), and no output
// folder is left behind.
TEST_F(SimulateDem, DrumRefusesTooThinSlab) {
  const auto r = run_feedflow(
      "simulate cases/rotating_drum_20rpm.toml --solver dem --time 1s --set dem.slab_depth=3mm --out run", dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("dem.slab_depth"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "run"));
}

}  // namespace
