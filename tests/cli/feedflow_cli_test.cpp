// Smoke tests of the real `feedflow` executable as a user runs it: output files, exit codes,
// stdout/stderr discipline.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

// A scratch folder holding a copy of cases/ (as a user's checkout would).
class FeedflowCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_folder("feedflow_cli", true);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The demo command: exit 0, a summary with units on stdout, results.json and results.txt written.
TEST_F(FeedflowCli, DesignPilotHopperWritesResults) {
  const auto r = run_feedflow("design cases/pilot_hopper.toml", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("semi angle                30 deg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Verdict:"), std::string::npos) << r.out;
  const auto json = nlohmann::json::parse(slurp(dir_ / "out/pilot_hopper/results.json"));
  EXPECT_EQ(json.at("case").at("name"), "pilot_hopper");
  EXPECT_EQ(json.at("case").at("kind"), "hopper");
  EXPECT_NEAR(json.at("inputs").at("hopper").at("outlet_width").get<double>(), 0.06, 1e-12);
  EXPECT_TRUE(json.at("results").is_object());
  EXPECT_TRUE(fs::exists(dir_ / "out/pilot_hopper/results.txt"));
}

// Each shipped case runs through `design` and records its kind.
TEST_F(FeedflowCli, DesignRunsEveryShippedCase) {
  for (const auto* name : {"inclined_plane_29_5", "inclined_plane_37", "rotating_drum_20rpm"}) {
    SCOPED_TRACE(name);
    const auto r = run_feedflow(std::string("design cases/") + name + ".toml -q", dir_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty()) << "quiet run printed: " << r.out;
    EXPECT_TRUE(fs::exists(dir_ / "out" / name / "results.json"));
  }
}

// --json - sends only valid JSON to stdout; --set values reach the resolved inputs.
TEST_F(FeedflowCli, JsonToStdoutAndSet) {
  const auto r = run_feedflow(
      "design cases/pilot_hopper.toml --json - --set hopper.semi_angle=32deg --set "
      "'material.bulk.density=250 kg/m^3'",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);  // throws if anything else is on stdout
  EXPECT_NEAR(json.at("inputs").at("hopper").at("semi_angle").get<double>(), 32 * M_PI / 180, 1e-12);
  EXPECT_NEAR(json.at("inputs").at("material").at("bulk").at("density").get<double>(), 250, 1e-12);
}

// --out and --json FILE put the files where asked.
TEST_F(FeedflowCli, OutFolderAndJsonFile) {
  const auto r = run_feedflow("design cases/rotating_drum_20rpm.toml --out runs/a --json r.json", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "runs/a/results.json"));
  EXPECT_TRUE(fs::exists(dir_ / "runs/a/results.txt"));
  EXPECT_EQ(nlohmann::json::parse(slurp(dir_ / "r.json")).at("case").at("kind"), "drum");
}

// Bad input: exit 2, the message names file, line and key, nothing on stdout, nothing written.
TEST_F(FeedflowCli, BadCaseExitsTwoAndWritesNothing) {
  std::ofstream(dir_ / "cases/bad.toml") << "[hopper]\nshape = \"wedge\"\nsemi_angle = \"30 mm\"\n";
  const auto r = run_feedflow("design cases/bad.toml", dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cases/bad.toml:3: hopper.semi_angle:"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
  const auto typo = run_feedflow("design cases/pilot_hopper.toml --set hopper.outlet_widht=5mm", dir_);
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_NE(typo.err.find("did you mean \"outlet_width\""), std::string::npos) << typo.err;
  EXPECT_EQ(run_feedflow("design cases/missing.toml", dir_).exit_code, 2);
  EXPECT_EQ(run_feedflow("design", dir_).exit_code, 2);            // usage
  EXPECT_EQ(run_feedflow("frobnicate", dir_).exit_code, 2);        // unknown subcommand
  EXPECT_EQ(run_feedflow("", dir_).exit_code, 2);                  // no subcommand
}

// simulate refuses a bad solver name, a time without a time unit, a missing checkpoint and a
// checkpoint interval that is no wall time with exit code 2, naming the option, before anything
// runs or is written.
TEST_F(FeedflowCli, SimulateBadOptionsExitTwo) {
  const struct {
    const char* cmd;
    const char* key;
  } cases[] = {{"simulate cases/pilot_hopper.toml --solver fem", "--solver"},
               {"simulate cases/pilot_hopper.toml --time 3mm", "--time"},
               {"simulate cases/pilot_hopper.toml --time -1s", "--time"},
               {"simulate cases/pilot_hopper.toml --restart nowhere.h5", "--restart"},
               {"simulate cases/pilot_hopper.toml --checkpoint-every 5mm", "--checkpoint-every"},
               {"simulate cases/pilot_hopper.toml --checkpoint-every -1min", "--checkpoint-every"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.cmd);
    const auto r = run_feedflow(std::string(c.cmd) + " --out sim_out", dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(c.key), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "sim_out"));
  }
}

// materials lists the pine; materials NAME shows every parameter with unit and source, and what
// `feedflow calibrate` fitted into it (the shipped pine: the hopper's discharge and the drum's
// flowing layer).
TEST_F(FeedflowCli, MaterialsListAndDetail) {
  const auto list = run_feedflow("materials", dir_);
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_NE(list.out.find("loblolly_pine"), std::string::npos);
  const auto one = run_feedflow("materials loblolly_pine", dir_);
  EXPECT_EQ(one.exit_code, 0);
  for (const char* text : {"187.6 kPa", "47.3 deg", "290 kg/m^3", "1.5 mm", "source: seed Table 2",
                           "[calibration] hopper discharge, wedge hoppers",
                           "[calibration.drum] flowing layer: c_delta"})
    EXPECT_NE(one.out.find(text), std::string::npos) << text;
  const auto json = nlohmann::json::parse(run_feedflow("materials loblolly_pine --json -", dir_).out);
  EXPECT_EQ(json.at("parameters").at("hypoplastic.h_s").at("value"), 187600.0);
  EXPECT_EQ(json.at("calibration").size(), 2u);
  EXPECT_EQ(run_feedflow("materials oak", dir_).exit_code, 2);
}

// cases lists every case file with its kind and description.
TEST_F(FeedflowCli, CasesListing) {
  const auto r = run_feedflow("cases", dir_);
  EXPECT_EQ(r.exit_code, 0);
  for (const char* name : {"pilot_hopper.toml", "inclined_plane_29_5.toml", "inclined_plane_37.toml",
                           "rotating_drum_20rpm.toml"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name;
  EXPECT_NE(r.out.find("drum"), std::string::npos);
}

// --help works on every subcommand; version prints the version.
TEST_F(FeedflowCli, HelpAndVersion) {
  for (const auto* cmd : {"--help", "design --help", "materials --help", "cases --help",
                          "simulate --help", "version --help"}) {
    SCOPED_TRACE(cmd);
    const auto r = run_feedflow(cmd, dir_);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << r.out;
  }
  EXPECT_NE(run_feedflow("version", dir_).out.find("feedflow 0."), std::string::npos);
}

// A throughput required in t/h is reported in t/h: the input as written, every mass flow rate
// and the margin table's requirement and achieved value, in results.txt, results.json (the SI
// value with display_unit "t/h") and the report re-rendered from the JSON; the rate itself is
// the same as with the target written in kg/s (5 t/h = 1.3889 kg/s).
TEST_F(FeedflowCli, ThroughputWrittenInTonnesPerHourIsReportedSo) {
  const auto r = run_feedflow(
      "design cases/pilot_hopper.toml --set \"design.required_throughput=5 t/h\" --set "
      "hopper.outlet_width=45mm --report --out th",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* text :
       {"required throughput       5 t/h", "mass flow rate                 >= 5 t/h"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
  const auto json = nlohmann::json::parse(slurp(dir_ / "th/results.json"));
  const auto& rate = json.at("results").at("mass_flow_rate");
  EXPECT_EQ(rate.at("unit"), "kg/s");
  EXPECT_EQ(rate.at("display_unit"), "t/h");
  const auto si = run_feedflow(
      "design cases/pilot_hopper.toml --set design.required_throughput=1.3889kg/s "
      "--set hopper.outlet_width=45mm --json - -q",
      dir_);
  const auto plain = nlohmann::json::parse(si.out);
  EXPECT_EQ(plain.at("results").at("mass_flow_rate").at("value"), rate.at("value"));
  EXPECT_FALSE(plain.at("results").at("mass_flow_rate").contains("display_unit"));
  ASSERT_EQ(run_feedflow("report th/results.json --out again -q", dir_).exit_code, 0);
  const std::string text = feedflow::testing::pdf_text(dir_ / "again/report.pdf", true);
  EXPECT_NE(text.find(">= 5 t/h"), std::string::npos) << text;
  EXPECT_NE(text.find("required throughput"), std::string::npos);
  EXPECT_EQ(text.find("1.389 kg/s"), std::string::npos) << "the target is shown as written";
}

}  // namespace

namespace {

// design --report writes a PDF and HTML; report regenerates them from results.json alone.
TEST_F(FeedflowCli, DesignReportAndReportCommand) {
  const auto r = run_feedflow("design cases/pilot_hopper.toml --report -q", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(fs::exists(dir_ / "out/pilot_hopper/report.pdf"));
  ASSERT_TRUE(fs::exists(dir_ / "out/pilot_hopper/report.html"));
  const auto again = run_feedflow("report out/pilot_hopper/results.json --out again", dir_);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_TRUE(fs::exists(dir_ / "again/report.pdf"));
  std::ofstream(dir_ / "bad.json") << "{\"feedflow\": 1";
  EXPECT_EQ(run_feedflow("report bad.json", dir_).exit_code, 2);
  std::ofstream(dir_ / "run.h5") << "x";
  EXPECT_EQ(run_feedflow("report run.h5", dir_).exit_code, 3);
}

}  // namespace

namespace {

// --model picks an alternative model; unknown keys or names are bad input (exit 2).
TEST_F(FeedflowCli, ModelChoice) {
  const auto r = run_feedflow("design cases/pilot_hopper.toml --model hopper.flow_factor=rsf --json -", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_NE(json.at("results").at("flow_factor").at("model").get<std::string>().find("radial stress field"),
            std::string::npos);
  fs::remove_all(dir_ / "out");
  const auto bad = run_feedflow("design cases/pilot_hopper.toml --model hopper.flow_factor=magic", dir_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--model: hopper.flow_factor"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// The design summary is a table of quantity, value, band, rung and model, with the verdict.
TEST_F(FeedflowCli, DesignPrintsResultTable) {
  const auto r = run_feedflow("design cases/pilot_hopper.toml", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* text : {"quantity", "band", "critical outlet width", " mm ", "mass flow rate", "kg/s",
                           "Verdict: PASS"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
}

// `feedflow simulate <small hopper case> --solver dem --time 0.3s`: exit 0, results.json with
// the DEM results on rung L3 beside the reduced model's, timeseries.csv with the discharged
// mass, the snapshots' XDMF sidecar and the checkpoint.
TEST_F(FeedflowCli, SimulateSmallHopperWithDemWritesL3Results) {
  fs::copy_file(fs::path(FEEDFLOW_SOURCE_DIR) / "tests/data/dem_hopper_twin.toml", dir_ / "twin.toml");
  const auto r = run_feedflow("simulate twin.toml --solver dem --time 0.3s --out sim", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(slurp(dir_ / "sim/results.json"));
  const auto& results = json.at("results");
  EXPECT_EQ(results.at("arching").at("rung"), "L3");
  EXPECT_EQ(results.at("mass_flow_rate").at("rung"), "L3");
  EXPECT_EQ(results.at("mass_flow_rate").at("unit"), "kg/s");
  EXPECT_GT(results.at("mass_flow_rate").at("value").get<double>(), 0.0);
  EXPECT_NE(results.at("mass_flow_rate_reduced_model").at("rung"), "L3");
  const std::string csv = slurp(dir_ / "sim/timeseries.csv");
  EXPECT_EQ(csv.rfind("time [s],time_after_opening [s],discharged_mass [kg]", 0), 0u) << csv.substr(0, 200);
  EXPECT_TRUE(fs::exists(dir_ / "sim/checkpoint.h5"));
  EXPECT_TRUE(fs::exists(dir_ / "sim/particles.xdmf"));
}

}  // namespace
