// `feedflow calibrate` as a user runs it: a small design of experiments on coarse CEL runs,
// the material file rewritten with its [calibration], a second run that reads the runs back, the
// design check that then uses the coefficients, and bad input refused by flag.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using namespace feedflow::testing;

namespace {

// Two fitted widths and one held out at 3 cells across the half outlet, 0.3 s each: the fit
// cannot make the fitted points worse than the published coefficients (least squares from
// them), the material file gains the table, `design` says it uses it, and the same command
// again makes no run.
TEST(CalibrateCommand, CalibratesTheMaterialFileAndDesignUsesIt) {
  const fs::path dir = scratch_folder("feedflow_calibrate", true);
  const std::string args =
      "calibrate loblolly_pine --against cel --outlet-widths \"100,140 mm\" --semi-angles \"30 deg\" "
      "--held-out \"120 mm@30 deg\" --cells-across 3 --time 0.3s --out c";
  const feedflow::testing::Run first = run_feedflow(args, dir);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("3 run(s) made, 0 read back"), std::string::npos) << first.out;
  const auto json = nlohmann::json::parse(slurp(dir / "c" / "calibration.json"));
  ASSERT_EQ(json["points"].size(), 3u);
  for (const auto& p : json["points"]) {
    EXPECT_EQ(p["status"], "done");
    EXPECT_GT(p["reference"]["value"].get<double>(), 0.0);
  }
  for (const auto& m : json["models"]) {
    if (!m["failure"].get<std::string>().empty()) continue;
    EXPECT_LE(m["fit_rms_error_after"].get<double>(), m["fit_rms_error_before"].get<double>() + 1e-12) << m["model"];
  }
  const std::string material = slurp(dir / "cases" / "materials" / "loblolly_pine.toml");
  EXPECT_NE(material.find("[calibration]"), std::string::npos);
  EXPECT_NE(material.find("against = \"cel\""), std::string::npos);
  EXPECT_NE(material.find("[[calibration.points]]"), std::string::npos);

  const feedflow::testing::Run design = run_feedflow("design cases/pilot_hopper.toml", dir);
  ASSERT_EQ(design.exit_code, 0) << design.err;
  EXPECT_NE(design.out.find("calibrated against L2 CEL-FEM"), std::string::npos) << design.out;

  const feedflow::testing::Run again = run_feedflow(args, dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("0 run(s) made, 3 read back"), std::string::npos) << again.out;
  fs::remove_all(dir);
}

// Bad input is exit 2 naming the flag, before any run: a list without a unit, too coarse a CEL
// level, levels that do not double, a held-out point without '@', one fitted point.
TEST(CalibrateCommand, BadInputIsRefusedByFlag) {
  const fs::path dir = scratch_folder("feedflow_calibrate", true);
  const std::pair<const char*, const char*> cases[] = {
      {"--outlet-widths 40,50", "--outlet-widths"},
      {"--cells-across 2,4", "--cells-across"},
      {"--cells-across 3,5", "--cells-across"},
      {"--held-out \"45 mm\"", "--held-out"},
      {"--outlet-widths \"60 mm\" --semi-angles \"30 deg\"", "--outlet-widths"},
  };
  for (const auto& [flags, flag] : cases) {
    const feedflow::testing::Run r = run_feedflow(std::string("calibrate loblolly_pine --against cel --out c ") + flags, dir);
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_NE(r.err.find(flag), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "c")) << flags;
  }
  EXPECT_EQ(run_feedflow("calibrate loblolly_pine --against fem", dir).exit_code, 2);
  fs::remove_all(dir);
}

}  // namespace
