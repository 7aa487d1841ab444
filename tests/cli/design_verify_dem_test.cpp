// `feedflow design --verify dem` on the DEM twin of the pilot hopper (Hertz, 6 mm spheres): a DEM
// run at the design outlet says whether it arches (rung L3, the reduced label beside it), and the
// interlocking width of the spheres is found by bisection on the outlet width.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using namespace feedflow::testing;

namespace {

nlohmann::json verify_json(const fs::path& dir, const std::string& flags) {
  const Run r = run_feedflow("design twin.toml -q --json - --verify dem " + flags, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

bool said(const nlohmann::json& j, const std::string& text) {
  for (const auto& reason : j["verdict"]["reasons"])
    if (reason.get<std::string>().find(text) != std::string::npos) return true;
  return false;
}

fs::path twin_folder() {
  const fs::path dir = scratch_folder("feedflow_verify_dem", false);
  fs::copy_file(fs::path(FEEDFLOW_SOURCE_DIR) / "tests/data/dem_hopper_twin.toml",
                dir / "twin.toml");
  return dir;
}

// The design outlet (60 mm, 10 sphere diameters) flows on the particle rung: "flowing" on rung
// L3 with the reduced label beside it, judged pass; a budget of 1 s cannot hold the bisection's 6
// more runs, which the verdict says with the time they would take, and nothing is half-verified.
TEST(DesignVerifyDem, DesignOutletObservedAndBisectionRefusedBeyondTheBudget) {
  const fs::path dir = twin_folder();
  const auto j = verify_json(dir, "--width-tolerance 2mm --budget 1s");
  EXPECT_EQ(j["results"]["arching"]["rung"], "L3");
  EXPECT_EQ(j["results"]["arching"]["value"], "flowing");
  EXPECT_EQ(j["results"]["arching_reduced_model"]["rung"], "L0");
  EXPECT_TRUE(said(j, "pass: the outlet flows (observed)"));
  EXPECT_TRUE(said(j, "the bisection needs 6 more DEM runs")) << j["verdict"]["reasons"];
  EXPECT_FALSE(j["results"].contains("mechanical_arching_width_dem_spheres"));
  fs::remove_all(dir);
}

// LONG (about a minute): the whole bisection. The spheres' interlocking width lies inside the
// rule's 3-8 d (18-48 mm) and is bracketed to 2 mm (arches below, flows above); it stands beside
// the material's own (reduced) width, which the coarse-grained spheres do not verify; the same
// command again reads every run back.
TEST(DesignVerifyDem, LONG_BisectionBracketsTheSpheresInterlockingWidth) {
  const fs::path dir = twin_folder();
  const auto j = verify_json(dir, "--width-tolerance 2mm --budget 30min");
  const auto& w = j["results"]["mechanical_arching_width_dem_spheres"];
  EXPECT_EQ(w["rung"], "L3");
  EXPECT_EQ(w["unit"], "mm");
  const double low = w["low"].get<double>(), high = w["high"].get<double>();
  EXPECT_GE(low, 18.0);
  EXPECT_LE(high, 48.0);
  EXPECT_LT(low, high);
  EXPECT_LE(high - low, 2.0 + 1e-9);
  EXPECT_EQ(j["results"]["mechanical_arching_width"]["rung"], "L0");
  EXPECT_TRUE(said(j, "mechanical arching width verified on the particle rung"));
  const auto again = verify_json(dir, "--width-tolerance 2mm --budget 30min");
  EXPECT_EQ(again["results"]["mechanical_arching_width_dem_spheres"], w);
  EXPECT_TRUE(said(again, "(0 s of runs)") || said(again, "; 0 s of runs)"));
  fs::remove_all(dir);
}

}  // namespace
