// The stepper contract (fullsim/common/stepper.hpp) as both engines implement it, and the scene
// run loop (fullsim/common/scene_run.hpp) on each: sampling on the step grid, the stop
// predicate, the interrupt with its checkpoint, and a restart that continues the same series.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <regex>
#include <sstream>

#include "fullsim/cel/cel_scene_run.hpp"
#include "fullsim/cel/hopper_scene.hpp"
#include "models/os/interrupt_request.hpp"
#include "fullsim/common/scene_run.hpp"
#include "fullsim/dem/dem_checkpoint.hpp"
#include "models/units/angle.hpp"
#include "tests/fullsim/cel/small_hopper.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("feedflow_scenerun_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// 64 frictional spheres settling in a closed box whose floor slides sideways.
DemEngine settling_block(double time_step = 0.0) {
  ParticleStore p;
  add_lattice(p, Vec3(2e-3, 2e-3, 1.6e-3), 4, 4, 4, 2.95e-3, 0.05);
  const Vec3 lower(0, 0, 0), upper(0.016, 0.016, 0.02);
  DemSettings settings = hertz_settings(0.5, 0.5, 0.1);
  settings.requested_time_step = time_step;
  DemEngine e(settings, SimulationBox{lower, upper, {false, false, false}}, p);
  e.add_wall(Wall::plane("floor", lower, Vec3::UnitZ()).moving(Vec3(0.02, 0, 0), Vec3::Zero()));
  add_side_walls(e, lower, upper);
  return e;
}

// The pilot hopper's 30 deg wedge, 60 mm outlet, 0.3 m bin filled 0.35 m, pine on 20 mm cells.
cel::CelScene small_hopper_scene() {
  return cel::make_hopper_scene(testing::small_wedge(), 8.5 * kDegree, {290.0, 0.7102}, 0.02);
}

SceneRunOptions block_options(const DemEngine& e, const fs::path& out, double duration) {
  SceneRunOptions o;
  o.out = out;
  o.origin = o.sample_origin = 0.0;
  o.duration = duration;
  o.sample_interval = 1e-3;
  o.columns = {{"time", "s"}, {"kinetic_energy", "J"}, {"z0", "m"}};
  o.sample = [&e] {
    return std::vector<double>{e.time(), e.kinetic_energy(), e.particles().position[0].z()};
  };
  return o;
}

// DEM (fixed step): a time planned on the step grid is met on its step whatever the round-off of
// the summed time; a time between steps is reached on the first step past it; whole_steps
// rounds to the nearest (at least one) or up; max_steps bounds a call.
TEST(StepperContract, FixedStepEngineMeetsTheStepGrid) {
  DemEngine e = settling_block();
  std::ostringstream log;
  e.prepare(log);
  const double dt = e.time_step();
  EXPECT_EQ(e.whole_steps(10.4 * dt, StepRounding::nearest), 10 * dt);
  EXPECT_EQ(e.whole_steps(0.2 * dt, StepRounding::nearest), dt);
  EXPECT_EQ(e.whole_steps(10.4 * dt, StepRounding::up), 11 * dt);
  EXPECT_EQ(e.whole_steps(10.0 * dt, StepRounding::up), 10 * dt);
  for (int k = 1; k <= 50; ++k) {  // 50 x 7 steps, each target planned on the grid
    e.advance_to(k * e.whole_steps(7.0 * dt, StepRounding::nearest));
    ASSERT_EQ(e.steps(), 7L * k);
  }
  EXPECT_EQ(e.advance_to(e.time() + 2.5 * dt), 3);  // first step past t
  EXPECT_TRUE(e.reached(e.time()));
  EXPECT_FALSE(e.reached(e.time() + 0.3 * dt));
  EXPECT_EQ(e.advance_to(e.time() + 100 * dt, 40), 40);  // bounded by max_steps
}

// CEL (adaptive step): advance_to ends on the first step past t, and returns right after the step
// in which the scene's event (the end of the gravity phase) happened, so the loop can plan the
// run's end from it.
TEST(StepperContract, AdaptiveStepEngineStopsPastTheTimeAndAtItsEvent) {
  cel::CelScene scene = small_hopper_scene();
  cel::CelSceneRun run(scene, make_hypoplastic_model(loblolly_pine_table1()));
  std::ostringstream log;
  run.prepare(log);
  EXPECT_NE(log.str().find("gravity phase"), std::string::npos);
  run.advance_to(0.05);
  EXPECT_GE(run.time(), 0.05);
  EXPECT_LT(run.time() - run.solver().last_dt(), 0.05);
  EXPECT_FALSE(run.event_started_at());
  run.advance_to(10.0);  // the gravity phase ends long before
  ASSERT_TRUE(run.event_started_at());
  EXPECT_EQ(*run.event_started_at(), run.time());
  EXPECT_LT(run.time(), 10.0);
}

// The loop samples on the step grid from the origin (a row every 1 ms = whole steps), runs to the
// end planned in whole steps, and a stop predicate ends it at the row that satisfies it.
TEST(SceneRun, SamplesOnTheStepGridAndStopsWhenAsked) {
  const fs::path dir = scratch("grid");
  DemEngine e = settling_block();
  SceneRunOptions o = block_options(e, dir, 0.02);
  SceneRunResult r = run_scene(e, o);
  EXPECT_EQ(r.end, RunEnd::duration);
  const double q = e.whole_steps(1e-3, StepRounding::nearest);
  ASSERT_EQ(r.series.rows().size(), 1u + static_cast<std::size_t>(std::floor(e.whole_steps(0.02, StepRounding::up) / q + 1e-9)));
  for (std::size_t k = 0; k < r.series.rows().size(); ++k)
    EXPECT_NEAR(r.series.rows()[k][0], k * q, 1e-3 * e.time_step());
  EXPECT_EQ(e.steps(), std::lround(e.whole_steps(0.02, StepRounding::up) / e.time_step()));

  DemEngine f = settling_block();
  SceneRunOptions stop = block_options(f, dir, 1.0);
  stop.stop = [](const TimeSeries& s) { return s.rows().size() == 5 ? std::string("five rows") : std::string(); };
  r = run_scene(f, stop);
  EXPECT_EQ(r.end, RunEnd::stopped);
  EXPECT_EQ(r.stop_reason, "five rows");
  EXPECT_EQ(r.series.rows().size(), 5u);
  fs::remove_all(dir);
}

// A user step that does not divide the sample interval rounds the interval up to whole steps;
// every sample inside the asked duration is still taken (20 rows after the origin for 20 ms at
// 1 ms), the last one on the step that ends the run.
TEST(SceneRun, UserStepKeepsTheLastSample) {
  const fs::path dir = scratch("user_step");
  DemEngine e = settling_block(1e-3 / 100.6);  // 1 ms is 100.6 steps: rounds to 101
  SceneRunOptions o = block_options(e, dir, 0.02);
  const SceneRunResult r = run_scene(e, o);
  ASSERT_EQ(r.series.rows().size(), 21u);
  EXPECT_NEAR(r.series.rows().back()[0], 20 * 101 * e.time_step(), 1e-3 * e.time_step());
  EXPECT_EQ(e.steps(), 20 * 101);
  fs::remove_all(dir);
}

// The times of the snapshots an XDMF sidecar lists (what ParaView shows) [s].
std::vector<double> xdmf_times(const fs::path& sidecar) {
  std::ifstream in(sidecar);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::regex time(R"re(<Time Value="([^"]+)"/>)re");
  std::vector<double> times;
  for (std::sregex_iterator it(text.begin(), text.end(), time), end; it != end; ++it)
    times.push_back(std::stod((*it)[1]));
  return times;
}

// Snapshots count from the sample origin, and an interval of whole sample intervals falls on
// the rows' steps: with a user step that does not divide 1 ms (101 steps a row, 503 for 5 ms
// on their own) and an origin 37 steps into the run, every snapshot's time is a row's time and
// there is one every 5 rows, the first at the origin.
TEST(SceneRun, SnapshotsFallOnRowsFromTheSampleOrigin) {
  const fs::path dir = scratch("snapshot_rows");
  DemEngine e = settling_block(1e-3 / 100.6);
  std::ostringstream log;
  e.prepare(log);
  e.run_steps(37);
  SceneRunOptions o = block_options(e, dir, 0.02);
  o.origin = o.sample_origin = e.time();
  o.snapshot_interval = 5e-3;
  const SceneRunResult r = run_scene(e, o);
  const std::vector<double> times = xdmf_times(dir / "particles.xdmf");
  ASSERT_EQ(r.series.rows().size(), 21u);
  ASSERT_EQ(times.size(), 5u);  // at 0, 5, 10, 15 and 20 ms after the origin
  for (std::size_t k = 0; k < times.size(); ++k)
    EXPECT_EQ(times[k], r.series.rows()[5 * k][0]) << "snapshot " << k;
  fs::remove_all(dir);
}

// An interrupt request (the Ctrl-C flag) stops the loop before its next step and leaves a
// readable checkpoint of the step reached.
TEST(SceneRun, InterruptWritesACheckpointBeforeStopping) {
  const fs::path dir = scratch("interrupt");
  DemEngine e = settling_block();
  std::ostringstream log;
  e.prepare(log);
  e.run_steps(10);
  request_interrupt();
  const SceneRunResult r = run_scene(e, block_options(e, dir, 1.0));
  clear_interrupt_request();
  EXPECT_EQ(r.end, RunEnd::interrupted);
  EXPECT_EQ(e.steps(), 10);
  EXPECT_EQ(read_dem_checkpoint(scene_checkpoint_path(dir)).step, 10);
}

// A DEM run stopped half way (its checkpoint) and continued by a new engine restored through the
// contract writes the same series, to the last bit, as the uninterrupted run.
TEST(SceneRun, RestartedDemRunContinuesTheSameSeries) {
  const fs::path whole = scratch("dem_whole"), first = scratch("dem_first"), second = scratch("dem_second");
  DemEngine a = settling_block();
  const SceneRunResult straight = run_scene(a, block_options(a, whole, 0.03));
  DemEngine b = settling_block();
  run_scene(b, block_options(b, first, 0.015));
  DemEngine c = settling_block();
  SceneRunOptions o = block_options(c, second, 0.03);
  o.restart = scene_checkpoint_path(first);
  o.previous = restore_scene_run(c, Hdf5File(o.restart, Hdf5File::Mode::read), o.columns);
  const SceneRunResult resumed = run_scene(c, o);
  EXPECT_GT(straight.series.rows().size(), 20u);
  EXPECT_EQ(resumed.series.rows(), straight.series.rows());
  EXPECT_EQ(c.steps(), a.steps());
  for (const auto& d : {whole, first, second}) fs::remove_all(d);
}

// The snapshot files in `dir` that ParaView could not open: an HDF5 file (other than the
// checkpoint) without its XDMF sidecar.
std::vector<std::string> snapshots_without_sidecar(const fs::path& dir) {
  std::vector<std::string> bare;
  for (const auto& f : fs::directory_iterator(dir)) {
    const fs::path p = f.path();
    if (p.extension() == ".h5" && p.filename() != "checkpoint.h5" && !fs::exists(fs::path(p).replace_extension(".xdmf")))
      bare.push_back(p.filename().string());
  }
  return bare;
}

// A restarted run stopped (Ctrl-C) before its first snapshot leaves no snapshot file at all
// (DEM and CEL): each file is made with its first snapshot, beside its sidecar.
TEST(SceneRun, RunStoppedBeforeItsFirstSnapshotLeavesNoBareFile) {
  const fs::path first = scratch("bare_first"), second = scratch("bare_second");
  DemEngine a = settling_block();
  SceneRunOptions o = block_options(a, first, 0.01);
  o.snapshot_interval = 0.005;
  run_scene(a, o);
  DemEngine b = settling_block();
  SceneRunOptions again = block_options(b, second, 0.03);
  again.snapshot_interval = 0.005;
  again.restart = scene_checkpoint_path(first);
  again.previous = restore_scene_run(b, Hdf5File(again.restart, Hdf5File::Mode::read), again.columns);
  request_interrupt();
  EXPECT_EQ(run_scene(b, again).end, RunEnd::interrupted);
  clear_interrupt_request();
  EXPECT_TRUE(fs::exists(scene_checkpoint_path(second)));
  EXPECT_EQ(snapshots_without_sidecar(second), std::vector<std::string>{});
  EXPECT_EQ(std::distance(fs::directory_iterator(second), fs::directory_iterator()), 1);  // the checkpoint

  const fs::path cel_second = scratch("bare_cel");
  const HypoplasticModel model = make_hypoplastic_model(loblolly_pine_table1());
  cel::CelSceneRun c(small_hopper_scene(), model);
  SceneRunOptions cel_run;
  cel_run.out = first;
  cel_run.origin = cel_run.sample_origin = 0.0;
  cel_run.duration = 0.01;
  cel_run.columns = {{"time", "s"}};
  cel_run.sample = [&c] { return std::vector<double>{c.time()}; };
  cel_run.snapshot_interval = 0.005;
  run_scene(c, cel_run);
  cel::CelSceneRun d(small_hopper_scene(), model);
  cel_run.sample = [&d] { return std::vector<double>{d.time()}; };
  cel_run.out = cel_second;
  cel_run.duration = 0.03;
  cel_run.restart = scene_checkpoint_path(first);
  cel_run.previous = restore_scene_run(d, Hdf5File(cel_run.restart, Hdf5File::Mode::read), cel_run.columns);
  request_interrupt();
  EXPECT_EQ(run_scene(d, cel_run).end, RunEnd::interrupted);
  clear_interrupt_request();
  EXPECT_EQ(snapshots_without_sidecar(cel_second), std::vector<std::string>{});
  EXPECT_FALSE(fs::exists(cel_second / "fields.h5"));
  for (const auto& dir : {first, second, cel_second}) fs::remove_all(dir);
}

// The same for a CEL scene run stopped in its gravity phase: the restarted run finds the event
// where the uninterrupted one did and samples the same rows.
TEST(SceneRun, RestartedCelRunContinuesTheSameSeries) {
  const fs::path whole = scratch("cel_whole"), first = scratch("cel_first"), second = scratch("cel_second");
  cel::CelScene scene = small_hopper_scene();
  scene.gravity.ramp_time = 0.3;
  scene.gravity.min_time = 0.35;
  const HypoplasticModel model = make_hypoplastic_model(loblolly_pine_table1());
  auto options = [](const cel::CelSceneRun& run, const fs::path& out, double latest) {
    SceneRunOptions o;
    o.out = out;
    o.latest_origin = latest;
    o.duration = 0.1;
    o.sample_at_origin = false;
    o.sample_interval = 0.01;
    o.columns = {{"time", "s"}, {"discharged", "kg/m"}, {"kinetic_energy", "J/m"}};
    o.sample = [&run] {
      return std::vector<double>{run.time(), run.solver().discharge().total(), run.solver().kinetic_energy()};
    };
    return o;
  };
  cel::CelSceneRun a(scene, model);
  const SceneRunResult straight = run_scene(a, options(a, whole, 2.0));
  cel::CelSceneRun b(scene, model);
  SceneRunOptions stop_early = options(b, first, 2.0);
  stop_early.stop = [](const TimeSeries& s) { return s.rows().size() == 20 ? std::string("halfway") : std::string(); };
  run_scene(b, stop_early);
  ASSERT_FALSE(b.event_started_at());  // stopped in the gravity phase
  cel::CelSceneRun c(scene, model);
  SceneRunOptions o = options(c, second, 2.0);
  o.restart = scene_checkpoint_path(first);
  o.previous = restore_scene_run(c, Hdf5File(o.restart, Hdf5File::Mode::read), o.columns);
  const SceneRunResult resumed = run_scene(c, o);
  ASSERT_TRUE(a.event_started_at());
  EXPECT_EQ(c.event_started_at(), a.event_started_at());
  EXPECT_GT(straight.series.rows().back()[1], 0.0);  // the outlet opened and mass left
  EXPECT_EQ(resumed.series.rows(), straight.series.rows());
  for (const auto& d : {whole, first, second}) fs::remove_all(d);
}

// A DEM run that checkpoints on the way and dies (an exception out of the loop, where a kill
// would leave nothing else) continues from its last checkpoint on the way to the same series, to
// the last bit, as the uninterrupted run.
TEST(SceneRun, ARunKilledOutrightContinuesFromItsLastCheckpointOnTheWay) {
  const fs::path whole = scratch("killed_whole"), first = scratch("killed_first"),
                 second = scratch("killed_second");
  DemEngine a = settling_block();
  const SceneRunResult straight = run_scene(a, block_options(a, whole, 0.03));
  DemEngine b = settling_block();
  SceneRunOptions dying = block_options(b, first, 0.03);
  dying.checkpoint_every = 1e-12;  // after every pass of the loop
  dying.stop = [](const TimeSeries& s) -> std::string {
    if (s.rows().size() == 17) throw std::runtime_error("killed");
    return "";
  };
  EXPECT_THROW(run_scene(b, dying), std::runtime_error);
  ASSERT_TRUE(fs::exists(scene_checkpoint_path(first)));
  DemEngine c = settling_block();
  SceneRunOptions o = block_options(c, second, 0.03);
  o.restart = scene_checkpoint_path(first);
  o.previous = restore_scene_run(c, Hdf5File(o.restart, Hdf5File::Mode::read), o.columns);
  EXPECT_GT(o.previous.rows().size(), 10u);  // it continues, not starts again
  EXPECT_LT(o.previous.rows().size(), 17u);
  const SceneRunResult resumed = run_scene(c, o);
  EXPECT_EQ(resumed.series.rows(), straight.series.rows());
  EXPECT_EQ(c.steps(), a.steps());
  for (const auto& d : {whole, first, second}) fs::remove_all(d);
}

}  // namespace
}  // namespace feedflow
