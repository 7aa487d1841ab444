// `feedflow sweep --rung L2` as a user runs it: every point a CEL simulation in its own folder;
// two MPI ranks (mpirun, as CI runs it, as root too) give the serial run's combined results; the
// same command again reads every point back; a point whose run was lost (killed before it was
// saved) is the only one run again.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

// Four coarse, short CEL points (20 mm cells put 3 or more cells across the half outlet).
const std::string kSweep =
    "sweep cases/pilot_hopper.toml --rung L2 --vary \"hopper.outlet_width=120,160 mm\" "
    "--vary \"hopper.semi_angle=25,30 deg\" --set cel.cell_size=20mm --time 0.01s ";

class SweepRanks : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_sweep_ranks", true); }
  void TearDown() override { fs::remove_all(dir_); }
  nlohmann::json sweep_json(const std::string& out) const {
    return nlohmann::json::parse(slurp(dir_ / out / "sweep.json"));
  }
  fs::path dir_;
};

// Each point's results, as the combined file lists them, but for the machine's speed (a
// throughput is measured, not computed).
void expect_same_points(const nlohmann::json& a, const nlohmann::json& b) {
  ASSERT_EQ(a.at("results"), b.at("results"));
  ASSERT_EQ(a.at("points").size(), b.at("points").size());
  for (std::size_t n = 0; n < a.at("points").size(); ++n) {
    const auto& p = a.at("points").at(n);
    const auto& q = b.at("points").at(n);
    EXPECT_EQ(p.at("inputs"), q.at("inputs"));
    EXPECT_EQ(p.at("status"), q.at("status")) << p.dump();
    EXPECT_EQ(p.value("verdict", ""), q.value("verdict", ""));
    for (std::size_t k = 0; k < a.at("results").size(); ++k) {
      const std::string key = a.at("results").at(k).at("key");
      if (key.find("per_second") == std::string::npos) {
        EXPECT_EQ(p.at("values").at(k), q.at("values").at(k)) << n << " " << key;
      }
    }
  }
}

TEST_F(SweepRanks, TwoRanksGiveTheSerialResultsAndRerunsReadPointsBack) {
  const auto serial = run_feedflow(kSweep + "--out serial", dir_);
  ASSERT_EQ(serial.exit_code, 0) << serial.err;
  const auto s = sweep_json("serial");
  ASSERT_EQ(s.at("points").size(), 4u);
  for (const auto& p : s.at("points")) {
    EXPECT_EQ(p.at("status"), "done") << p.dump();
    EXPECT_EQ(p.at("rung"), "L2");
    EXPECT_TRUE(fs::exists(dir_ / "serial" / p.at("folder").get<std::string>() / "run.json"));
  }
  EXPECT_EQ(s.at("timing").at("points_run"), 4);

  // Two ranks share the points and rank 0 writes the same combined results.
  const std::string mpirun = std::string(FEEDFLOW_MPIEXEC) +
                             " --oversubscribe --allow-run-as-root -np 2 '" FEEDFLOW_EXECUTABLE
                             "' ";
  const std::string command =
      "cd '" + dir_.string() + "' && " + mpirun + kSweep + "--out ranks > ranks.out 2> ranks.err";
  ASSERT_EQ(std::system(command.c_str()), 0) << slurp(dir_ / "ranks.err");
  const auto r = sweep_json("ranks");
  EXPECT_EQ(r.at("timing").at("ranks"), 2);
  EXPECT_EQ(r.at("timing").at("points_run"), 4);
  expect_same_points(s, r);

  // Again: every point is read back, none run.
  const auto again = run_feedflow(kSweep + "--out serial", dir_);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(sweep_json("serial").at("timing").at("points_read_back"), 4);
  EXPECT_EQ(sweep_json("serial").at("timing").at("points_run"), 0);
  expect_same_points(s, sweep_json("serial"));

  // A point killed before it saved its run: only that one is run again.
  fs::remove(dir_ / "serial/points/p0002/run.json");
  const auto resumed = run_feedflow(kSweep + "--out serial", dir_);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(sweep_json("serial").at("timing").at("points_run"), 1);
  EXPECT_EQ(sweep_json("serial").at("timing").at("points_read_back"), 3);
  expect_same_points(s, sweep_json("serial"));
}

// --verify cel: each point's discharge rate verified on the continuum rung as design --verify
// does it: the point stands on L2 with the CEL rate (its band from the Richardson error bar) and
// the verdict says verified; run again, the point is read back.
TEST_F(SweepRanks, VerifiedPointsStandOnTheContinuumRung) {
  const std::string sweep =
      "sweep cases/pilot_hopper.toml --vary \"hopper.outlet_width=200 mm\" --verify cel "
      "--tolerance 40% --out v";
  const auto r = run_feedflow(sweep, dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = sweep_json("v");
  const auto& p = j.at("points").at(0);
  EXPECT_EQ(p.at("rung"), "L2") << p.dump();
  const auto run = nlohmann::json::parse(slurp(dir_ / "v/points/p0000/run.json"));
  EXPECT_EQ(run.at("results").at("mass_flow_rate").at("rung"), "L2");
  EXPECT_NE(run.at("verdict").at("reasons").dump().find("mass flow rate verified on the "
                                                        "continuum rung"),
            std::string::npos);
  ASSERT_EQ(run_feedflow(sweep, dir_).exit_code, 0);
  EXPECT_EQ(sweep_json("v").at("timing").at("points_read_back"), 1);
}

// --solve-for with --verify cel: the outlet that delivers 25 kg/s is solved on the reduced rung,
// then checked there on the continuum rung: the point keeps its solve and stands on L2, its run
// made at the solved width.
TEST_F(SweepRanks, SolvedAnswersAreVerifiedWhereTheyLie) {
  const auto r = run_feedflow(
      "sweep cases/pilot_hopper.toml --solve-for hopper.outlet_width=120..240mm:4 "
      "--target mass_flow_rate=25kg/s --solve-tolerance 1mm --verify cel --tolerance 40% --out sv",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = sweep_json("sv");
  const auto& p = j.at("points").at(0);
  ASSERT_EQ(p.at("solution").at("outcome"), "solved") << p.dump();
  EXPECT_EQ(p.at("rung"), "L2");
  const auto run = nlohmann::json::parse(slurp(dir_ / "sv/points/p0000/run.json"));
  EXPECT_NE(run.at("invocation")
                .get<std::string>()
                .find("hopper.outlet_width=" + p.at("solution").at("text").get<std::string>()),
            std::string::npos);
  EXPECT_EQ(run.at("results").at("mass_flow_rate").at("rung"), "L2");
  EXPECT_NE(r.out.find("verified there on L2"), std::string::npos) << r.out;
}

// A point the solver refuses (20 mm cells put 1.5 across a 60 mm outlet's half) is recorded
// with its reason and the sweep goes on to the next.
TEST_F(SweepRanks, AFailedPointIsRecordedAndTheSweepGoesOn) {
  const auto r = run_feedflow(
      "sweep cases/pilot_hopper.toml --rung L2 --vary \"hopper.outlet_width=60,160 mm\" "
      "--set cel.cell_size=20mm --time 0.01s --out f",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = sweep_json("f");
  EXPECT_EQ(j.at("points").at(0).at("status"), "failed");
  EXPECT_NE(
      j.at("points").at(0).at("reason").get<std::string>().find("cells across the half outlet"),
      std::string::npos);
  EXPECT_EQ(j.at("points").at(1).at("status"), "done");
}

}  // namespace
