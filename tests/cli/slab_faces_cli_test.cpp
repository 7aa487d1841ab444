// `[dem] slab_faces` as a user sets it: the choice reaches the hopper run (its plan and the
// assumptions of its results), a bad value or a choice a scene cannot take is refused naming
// the key (exit 2).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

class SlabFacesCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_slabfaces", true); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// Frictionless faces on the reduced hopper twin (R = 3 mm, 6.6 mm slab): the plan names the
// frictionless front and back planes, and results.json states them among the assumptions.
TEST_F(SlabFacesCli, FrictionlessFacesReachTheHopperRun) {
  fs::copy_file(fs::path(FEEDFLOW_SOURCE_DIR) / "tests/data/dem_hopper_twin.toml",
                dir_ / "twin.toml");
  const auto r = run_feedflow(
      "simulate twin.toml --solver dem --time 0.05s --set dem.slab_depth=6.6mm "
      "--set dem.slab_faces=frictionless --out sim",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("slab faces: frictionless front and back planes"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("plane 'front'"), std::string::npos) << r.out;
  const auto json = nlohmann::json::parse(slurp(dir_ / "sim/results.json"));
  bool stated = false;
  for (const auto& a : json.at("assumptions"))
    if (a.get<std::string>().find("slab faces ([dem] slab_faces): frictionless") !=
        std::string::npos)
      stated = true;
  EXPECT_TRUE(stated) << json.at("assumptions").dump(1);
}

// A value that is not one of the four, periodic faces on a one-layer hopper slab, planar ones
// on a slab deeper than one layer, and flat faces on the drum's periodic slab are refused with
// exit 2 naming dem.slab_faces and where it came from, writing nothing.
TEST_F(SlabFacesCli, BadFacesAreRefusedNamingTheKey) {
  fs::copy_file(fs::path(FEEDFLOW_SOURCE_DIR) / "tests/data/dem_hopper_twin.toml",
                dir_ / "twin.toml");
  for (const char* cmd :
       {"simulate twin.toml --solver dem --time 0.05s --set dem.slab_faces=sticky --out a",
        "simulate twin.toml --solver dem --time 0.05s --set dem.slab_depth=6.6mm --set "
        "dem.slab_faces=periodic --out b",
        "simulate twin.toml --solver dem --time 0.05s --set dem.slab_depth=6.6mm --set "
        "dem.slab_faces=planar --out d",
        "simulate cases/rotating_drum_20rpm.toml --solver dem --time 0.05s --set "
        "dem.slab_depth=18mm "
        "--set dem.slab_faces=frictionless --out c"}) {
    const auto r = run_feedflow(cmd, dir_);
    EXPECT_EQ(r.exit_code, 2) << cmd << "\n" << r.err;
    EXPECT_NE(r.err.find("dem.slab_faces"), std::string::npos) << cmd << "\n" << r.err;
    // where the value came from: the case file or the --set override
    EXPECT_TRUE(r.err.find(".toml: dem.slab_faces") != std::string::npos ||
                r.err.find("--set: dem.slab_faces") != std::string::npos)
        << cmd << "\n" << r.err;
  }
  for (const char* out : {"a", "b", "c", "d"}) EXPECT_FALSE(fs::exists(dir_ / out)) << out;
}

}  // namespace
