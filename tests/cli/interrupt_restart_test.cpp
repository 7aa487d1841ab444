// Ctrl-C at any moment of a run, as a user presses it: `feedflow simulate` gets SIGINT at wall
// times spread over its phases (the DEM fill, the CEL gravity phase, the flow). Each interrupted
// run either writes a checkpoint (exit 130) whose restart ends with the same time series and the
// same results as the uninterrupted run (a checkpoint of the DEM fill continues the fill), or,
// interrupted before the fill's first batch is in, says that no checkpoint was written (exit
// 130, nothing to continue) — never anything else.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "fullsim/common/hdf5_file.hpp"
#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using namespace feedflow::testing;

namespace {

struct Interrupted {
  int exit_code = -1;
  std::string err;
};

// Starts `args` in `dir`, sends SIGINT after `after`, and waits for the run to end.
Interrupted interrupt_after(const fs::path& dir, const std::vector<std::string>& args, std::chrono::milliseconds after) {
  ChildRun run;
  run.folder = dir;
  run.args = args;
  const pid_t pid = detail::spawn(FEEDFLOW_EXECUTABLE, run);
  std::this_thread::sleep_for(after);
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  Interrupted r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(dir / ".stderr");
  return r;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  for (std::size_t a = 0; a < s.size();) {
    const std::size_t b = std::min(s.find(' ', a), s.size());
    if (b > a) out.push_back(s.substr(a, b - a));
    a = b + 1;
  }
  return out;
}

// The results that a restart must reproduce: every value, unit and band (not the run times).
nlohmann::json physics(const fs::path& results) {
  nlohmann::json j = nlohmann::json::parse(slurp(results)).at("results");
  for (const char* wall : {"run_wall_time", "cell_updates_per_second"}) j.erase(wall);
  for (auto& [key, e] : j.items())
    for (const char* text : {"model", "source"}) e.erase(text);
  return j;
}

struct Checkpointed {
  int any = 0;
  int during_fill = 0;  // checkpoints of a DEM fill under way (a /fill group)
};

// Runs `scene` straight to `time`, then interrupted at each fraction of the straight run's wall
// time (so the phases are hit on a fast or a loaded machine) and restarted to `time`; returns how
// many interruptions left a checkpoint.
Checkpointed interrupted_runs_match(const fs::path& dir, const std::string& scene, const std::string& time,
                           std::initializer_list<double> fractions) {
  const auto start = std::chrono::steady_clock::now();
  const auto straight = run_feedflow(scene + " -q --time " + time + " --out straight", dir);
  const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(straight.exit_code, 0) << straight.err;
  Checkpointed checkpointed;
  std::vector<double> tries(fractions);
  // On a loaded machine the phases shift: without a checkpoint yet, try later moments too.
  for (double late : {0.8, 0.9, 0.95}) tries.push_back(late);
  for (std::size_t t = 0; t < tries.size(); ++t) {
    if (t >= fractions.size() && checkpointed.any > 0) break;
    const int wait = static_cast<int>(tries[t] * wall_ms);
    const std::string cut = "cut" + std::to_string(t), again = "again" + std::to_string(t);
    const Interrupted r = interrupt_after(dir, split(scene + " -q --time " + time + " --out " + cut),
                                          std::chrono::milliseconds(wait));
    if (r.exit_code == 0) continue;  // finished before the signal: nothing to test at this wait
    if (r.exit_code == -1 && !fs::exists(dir / cut)) continue;  // stopped by the signal before it began
    EXPECT_EQ(r.exit_code, 130) << "after " << wait << " ms: " << r.err;
    if (r.exit_code != 130) continue;
    if (!fs::exists(dir / cut / "checkpoint.h5")) {
      EXPECT_NE(r.err.find("before a checkpoint"), std::string::npos) << r.err;
      continue;
    }
    ++checkpointed.any;
    if (feedflow::Hdf5File(dir / cut / "checkpoint.h5", feedflow::Hdf5File::Mode::read).exists("/fill"))
      ++checkpointed.during_fill;
    const auto resumed =
        run_feedflow(scene + " -q --time " + time + " --restart " + cut + "/checkpoint.h5 --out " + again, dir);
    EXPECT_EQ(resumed.exit_code, 0) << "after " << wait << " ms: " << resumed.err;
    if (resumed.exit_code != 0) continue;
    EXPECT_EQ(slurp(dir / again / "timeseries.csv"), slurp(dir / "straight" / "timeseries.csv"))
        << "interrupted after " << wait << " ms";
    EXPECT_EQ(physics(dir / again / "results.json"), physics(dir / "straight" / "results.json"))
        << "interrupted after " << wait << " ms";
  }
  return checkpointed;
}

class InterruptRestart : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_interrupt", true); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The CEL hopper on 20 mm cells (a 120 mm outlet: 3 cells across its half): interrupted in the
// gravity phase and in the discharge.
TEST_F(InterruptRestart, CelHopperAnyPhase) {
  const std::string scene =
      "simulate cases/pilot_hopper.toml --solver cel --set cel.cell_size=20mm --set hopper.outlet_width=120mm";
  EXPECT_GE(interrupted_runs_match(dir_, scene, "0.3s", {0.1, 0.5, 0.85}).any, 1);
}

// LONG (about 50 s): the DEM drum twin: interrupted twice while filling (the fill continues from
// its checkpoint) and twice while turning (the fill takes about half the wall time of a 1 s run).
// Fast counterparts: DemHopperAnyPhase (a DEM fill and run cut by the signal and continued) and
// SimulateDem.DrumRestartContinuesTheSameSeries (a turning drum continued to the same bits).
TEST_F(InterruptRestart, LONG_DemDrumAnyPhase) {
  const std::string scene =
      "simulate cases/rotating_drum_20rpm.toml --solver dem --set dem.slab_depth=18mm --set dem.normal_law=hertz "
      "--set material.dem.particle.radius=3mm";
  const Checkpointed c = interrupted_runs_match(dir_, scene, "1s", {0.15, 0.3, 0.75, 0.9});
  EXPECT_GE(c.any, 2);
  EXPECT_GE(c.during_fill, 1);
}

// The DEM hopper twin: interrupted while filling and while discharging.
TEST_F(InterruptRestart, DemHopperAnyPhase) {
  fs::copy_file(FEEDFLOW_TEST_DATA_DIR "/dem_hopper_twin.toml", dir_ / "dem_hopper_twin.toml");
  const Checkpointed c =
      interrupted_runs_match(dir_, "simulate dem_hopper_twin.toml --solver dem", "0.5s", {0.1, 0.2, 0.7, 0.85});
  EXPECT_GE(c.any, 2);
  EXPECT_GE(c.during_fill, 1);
}

// The CEL drum (20 mm cells) and the CEL chute: interrupted in the gravity phase and after.
TEST_F(InterruptRestart, CelDrumAndChuteAnyPhase) {
  EXPECT_GE(interrupted_runs_match(dir_, "simulate cases/rotating_drum_20rpm.toml --solver cel --set cel.cell_size=20mm",
                                   "0.5s", {0.2, 0.8}).any,
            1);
  fs::remove_all(dir_ / "straight");
  EXPECT_GE(interrupted_runs_match(dir_,
                                   "simulate cases/inclined_plane_29_5.toml --solver cel --set cel.cell_size=20mm "
                                   "--set chute.bin_length=100mm --set chute.bin_height=0.16m --set chute.fill_height=80mm "
                                   "--set chute.length=0.4m --set chute.gate_opening=50mm",
                                   "0.5s", {0.3, 0.8}).any,
            1);
}

}  // namespace
