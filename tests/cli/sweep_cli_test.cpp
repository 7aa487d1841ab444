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

}  // namespace
