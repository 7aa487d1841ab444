// `feedflow sweep` as a user runs it: the files it writes, and bad input refused with exit 2
// naming the flag and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

class SweepCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_sweep", true); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::size_t lines(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}

// Semi-angle x outlet width on the pilot hopper: 54 points in sweep.json, sweep.csv (a header
// and a row each, units in the headers) and sweep.txt; a narrower outlet never passes where a
// wider one at the same angle fails (the critical outlet width is one threshold).
TEST_F(SweepCli, GridOfTheDesignCheckIsWritten) {
  const auto r = run_feedflow(
      "sweep cases/pilot_hopper.toml --vary hopper.semi_angle=15..40deg/5deg "
      "--vary hopper.outlet_width=20..100mm:9 --out s",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("54 points:"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(dir_ / "s/sweep.json"));
  ASSERT_EQ(j.at("points").size(), 54u);
  EXPECT_EQ(j.at("vary").at(1).at("unit"), "mm");
  const std::string csv = slurp(dir_ / "s/sweep.csv");
  EXPECT_EQ(lines(csv), 55u);
  EXPECT_NE(csv.find("hopper.outlet_width [mm]"), std::string::npos);
  EXPECT_NE(csv.find("mass_flow_rate [kg/s]"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "s/sweep.txt"));
  for (std::size_t angle = 0; angle < 6; ++angle) {
    bool failed_wider = false;
    for (std::size_t w = 9; w-- > 0;) {
      const auto& p = j.at("points").at(angle * 9 + w);
      const bool arching_fails =
          p.at("verdict") == "fail" &&
          p.at("governing").dump().find("critical_outlet_width") != std::string::npos;
      EXPECT_FALSE(failed_wider && p.at("verdict") == "pass") << p.dump();
      failed_wider = failed_wider || arching_fails;
    }
  }
}

// Bad ranges exit 2 naming --vary and what was expected, before anything is written.
TEST_F(SweepCli, BadRangesExitTwoAndWriteNothing) {
  for (const char* vary : {"hopper.semi_angle=15..40/5", "hopper.semi_angel=15..40deg/5deg",
                           "hopper.outlet_width=100..20mm:9", "hopper.outlet_width=20..100mm"}) {
    SCOPED_TRACE(vary);
    const auto r = run_feedflow(
        std::string("sweep cases/pilot_hopper.toml --vary ") + vary + " --out s", dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--vary"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "s"));
  }
  // Every point refused by the case (outlets wider than the 0.6 m bin) is bad input too.
  const auto none = run_feedflow(
      "sweep cases/pilot_hopper.toml --vary \"hopper.outlet_width=0.7,0.8 m\" --out s", dir_);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("no point of the sweep could be checked"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(dir_ / "s"));
  // Without --vary, the command says what it needs.
  EXPECT_EQ(run_feedflow("sweep cases/pilot_hopper.toml", dir_).exit_code, 2);
}

// The question the issue was filed with, one command: the smallest passing outlet for
// semi-angles 15-40 deg. Each angle is solved, passes there, and sits at the arching rule's
// boundary (1.2 x the top of B_c's band) to the 0.05 mm asked.
TEST_F(SweepCli, SolveForTheSmallestPassingOutletOverAngles) {
  const auto r = run_feedflow(
      "sweep cases/pilot_hopper.toml --vary hopper.semi_angle=15..40deg/5deg "
      "--solve-for hopper.outlet_width=20..200mm:10 --target pass --solve-tolerance 0.05mm "
      "--out s",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("smallest hopper.outlet_width that passes"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(dir_ / "s/sweep.json"));
  EXPECT_EQ(j.at("solve").at("key"), "hopper.outlet_width");
  EXPECT_DOUBLE_EQ(j.at("solve").at("tolerance").get<double>(), 0.05);
  ASSERT_EQ(j.at("points").size(), 6u);
  std::size_t bc = 0;
  while (j.at("results").at(bc).at("key") != "critical_outlet_width") ++bc;
  for (const auto& p : j.at("points")) {
    const auto& s = p.at("solution");
    ASSERT_EQ(s.at("outcome"), "solved") << p.dump();
    const auto& bracket = s.at("bracket");
    EXPECT_LE(bracket.at(1).get<double>() - bracket.at(0).get<double>(), 0.05 + 1e-9);
    EXPECT_EQ(p.at("verdict"), "pass");
    EXPECT_EQ(s.at("beyond").at("governing").at(0), "critical_outlet_width");
    EXPECT_NEAR(s.at("value").get<double>(), 1.2e3 * p.at("high").at(bc).get<double>(), 0.05);
  }
  const std::string csv = slurp(dir_ / "s/sweep.csv");
  EXPECT_NE(csv.find("hopper.outlet_width solved [mm]"), std::string::npos);
  EXPECT_EQ(lines(csv), 7u);
}

// Solve faults exit 2 naming the flag: no range to search, no target, a target the range
// cannot meet (with the nearest value's reason), and nothing is written.
TEST_F(SweepCli, BadSolvesExitTwoAndWriteNothing) {
  const std::pair<const char*, const char*> cases[] = {
      {"--solve-for hopper.outlet_width --target pass", "--solve-for"},
      {"--solve-for hopper.outlet_width=20..100mm:5", "--target"},
      {"--solve-for hopper.outlet_width=20..100mm:5 --target flow_pattern>=mass", "--target"},
      {"--solve-for hopper.outlet_width=10..20mm:3 --target pass", "--target"},
      {"--vary hopper.semi_angle=15..30deg:2 --target pass", "--target"}};
  for (const auto& [flags, flag] : cases) {
    SCOPED_TRACE(flags);
    const auto r =
        run_feedflow(std::string("sweep cases/pilot_hopper.toml ") + flags + " --out s", dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "s"));
  }
  const auto never = run_feedflow(
      "sweep cases/pilot_hopper.toml --solve-for hopper.outlet_width=10..20mm:3 --target pass",
      dir_);
  EXPECT_NE(never.err.find("the range cannot meet it: no hopper.outlet_width in 10 mm .. 20 mm "
                           "passes; nearest at 20 mm: fail"),
            std::string::npos)
      << never.err;
}

// A Latin hypercube of 20 points over two ranges: 20 rows, each value inside its range, the
// same points for the same seed.
TEST_F(SweepCli, LatinHypercubeSample) {
  const std::string sweep =
      "sweep cases/pilot_hopper.toml --vary hopper.semi_angle=15..40deg:2 "
      "--vary hopper.outlet_width=20..100mm:2 --sample lhs:20:5 ";
  const auto r = run_feedflow(sweep + "--out a", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = nlohmann::json::parse(slurp(dir_ / "a/sweep.json"));
  EXPECT_EQ(a.at("sample"), "latin hypercube");
  ASSERT_EQ(a.at("points").size(), 20u);
  for (const auto& v : a.at("vary").at(0).at("values_si")) {
    EXPECT_GE(v.get<double>(), 15.0 * 3.14159265358979 / 180 - 1e-9);
    EXPECT_LE(v.get<double>(), 40.0 * 3.14159265358979 / 180 + 1e-9);
  }
  ASSERT_EQ(run_feedflow(sweep + "--out b", dir_).exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(slurp(dir_ / "b/sweep.json")).at("vary"), a.at("vary"));
  EXPECT_EQ(run_feedflow(sweep + "--sample lhs:1 --out c", dir_).exit_code, 2);
}

// --report: report.pdf and report.html with the table and the design charts (the verdict map
// over the two keys and the judged results against the first).
TEST_F(SweepCli, ReportCarriesTheCharts) {
  const auto r = run_feedflow(
      "sweep cases/pilot_hopper.toml --vary hopper.semi_angle=15..40deg/5deg "
      "--vary hopper.outlet_width=20..100mm:9 --report --out s",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = slurp(dir_ / "s/report.html");
  EXPECT_NE(html.find("Verdict over semi_angle and outlet_width"), std::string::npos);
  EXPECT_NE(html.find("critical_outlet_width against semi_angle"), std::string::npos);
  EXPECT_GE(static_cast<int>(fs::file_size(dir_ / "s/report.pdf")), 20000);
  const auto solve = run_feedflow(
      "sweep cases/pilot_hopper.toml --vary hopper.semi_angle=15..35deg/5deg "
      "--solve-for hopper.outlet_width=20..200mm:10 --target pass --report --out t",
      dir_);
  ASSERT_EQ(solve.exit_code, 0) << solve.err;
  EXPECT_NE(slurp(dir_ / "t/report.html").find("The outlet_width that passes against semi_angle"),
            std::string::npos);
}

}  // namespace
