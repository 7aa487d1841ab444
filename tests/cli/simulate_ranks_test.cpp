// `feedflow simulate --solver dem` under mpirun, as a user runs it on a cluster: the ranks share
// one run (each its part of the particles), the first writes the folder and the log once, and
// the checkpoint it writes is one run's, so it continues on any number of processes. The CEL
// solver, which runs in one process, is refused under mpirun with the way to share runs.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

// The drum's reduced twin (coarse spheres, Hertz, 18 mm slab).
const std::string kDrum =
    "simulate cases/rotating_drum_20rpm.toml --solver dem --set dem.slab_depth=18mm "
    "--set dem.normal_law=hertz --set material.dem.particle.radius=3mm ";

class SimulateRanks : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_simulate_ranks", true); }
  void TearDown() override { fs::remove_all(dir_); }
  // The exit status of `command` run by feedflow under mpirun on two ranks, with stdout and
  // stderr in `name`.out and `name`.err.
  int on_two_ranks(const std::string& command, const std::string& name) const {
    const std::string line = "cd '" + dir_.string() + "' && " + std::string(FEEDFLOW_MPIEXEC) +
                             " --oversubscribe --allow-run-as-root -np 2 '" FEEDFLOW_EXECUTABLE
                             "' " + command + " > " + name + ".out 2> " + name + ".err";
    const int status = std::system(line.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  nlohmann::json results(const std::string& out) const {
    return nlohmann::json::parse(slurp(dir_ / out / "results.json")).at("results");
  }
  fs::path dir_;
};

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Two ranks share the drum's run (0.6 s of turning): one folder with the results, the log
// written once, the performance block showing both ranks; the bed and its angle those of a run
// alone to the spread of runs whose round-off the contacts amplify (the bed within 2 %, a trim
// through the top layer; each angle inside the other's band of sampled angles, the same
// regime); and the checkpoint the first rank wrote continues alone.
TEST_F(SimulateRanks, DemDrumSharedByTwoRanksIsOneRun) {
  const auto alone = run_feedflow(kDrum + "--time 0.6s --out alone", dir_);
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  ASSERT_EQ(on_two_ranks(kDrum + "--time 0.6s --out two", "two"), 0) << slurp(dir_ / "two.err");
  const std::string log = slurp(dir_ / "two.out");
  EXPECT_EQ(occurrences(log, "the DEM run shared among 2 MPI ranks"), 1u) << log;
  EXPECT_EQ(occurrences(log, "Verdict:"), 1u);
  EXPECT_NE(log.find("own particles"), std::string::npos);  // the balance line of the block
  const auto one = results("alone"), two = results("two");
  const double n1 = one.at("particles").at("value"), n2 = two.at("particles").at("value");
  EXPECT_NEAR(n2, n1, 0.02 * n1);
  const auto& a1 = one.at("dynamic_angle_of_repose");
  const auto& a2 = two.at("dynamic_angle_of_repose");
  EXPECT_GE(a2.at("value").get<double>(), a1.at("low").get<double>());
  EXPECT_LE(a2.at("value").get<double>(), a1.at("high").get<double>());
  EXPECT_GE(a1.at("value").get<double>(), a2.at("low").get<double>());
  EXPECT_LE(a1.at("value").get<double>(), a2.at("high").get<double>());
  EXPECT_EQ(two.at("regime").at("rung"), "L3");
  EXPECT_EQ(two.at("regime").at("value"), one.at("regime").at("value"));
  EXPECT_TRUE(fs::exists(dir_ / "two/checkpoint.h5"));
  EXPECT_TRUE(fs::exists(dir_ / "two/particles.h5"));

  const auto more = run_feedflow(kDrum + "--time 0.8s --restart two/checkpoint.h5 --out more", dir_);
  ASSERT_EQ(more.exit_code, 0) << more.err;
  EXPECT_EQ(results("more").at("particles").at("value").get<double>(), n2);
}

// The CEL-FEM solver runs in one process: under mpirun it exits 2, once, naming mpirun and the
// way to share whole runs, with no folder written.
TEST_F(SimulateRanks, CelUnderTwoRanksRefusesWithTheWayToShareRuns) {
  EXPECT_EQ(on_two_ranks("simulate cases/pilot_hopper.toml --solver cel --out s", "s"), 2);
  const std::string err = slurp(dir_ / "s.err");
  EXPECT_EQ(occurrences(err, "feedflow: error"), 1u) << err;
  EXPECT_NE(err.find("mpirun"), std::string::npos) << err;
  EXPECT_NE(err.find("feedflow sweep --rung L2"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(dir_ / "s"));
}

}  // namespace
