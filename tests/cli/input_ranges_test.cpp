// Input out of a model's range ends in exit 2 naming the key and its valid range, never in an
// internal error, a numerical failure, a non-finite result or a silent acceptance; case-local
// materials are found and checked.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

class InputRanges : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_ranges", true); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

struct Refused {
  const char* command;
  const char* names;  // the key and what the message must say of its range
  const char* range;
};

// Each reproducer of issue 21 (internal errors, exit 4, non-finite results, silent acceptance)
// is refused up front: exit 2, the key and its valid range named, nothing written.
TEST_F(InputRanges, OutOfRangeInputIsRefusedNamingTheKeyAndRange) {
  const Refused cases[] = {
      {"design cases/pilot_hopper.toml --set hopper.wall_friction_angle=60deg",
       "hopper.wall_friction_angle", "below the effective angle of internal friction (50 deg)"},
      {"design cases/pilot_hopper.toml --set hopper.wall_friction_angle=0deg",
       "hopper.wall_friction_angle", "above the wall-friction uncertainty (2 deg"},
      {"design cases/pilot_hopper.toml --set hopper.outlet_width=1mm", "hopper.outlet_width",
       "must exceed 1.5 median grain sizes (1.23 mm"},
      {"design cases/pilot_hopper.toml --set hopper.outlet_width=1mm --model "
       "hopper.discharge=brown",
       "hopper.outlet_width", "must exceed 1.5 median grain sizes"},
      {"design cases/inclined_plane_29_5.toml --set chute.length=1mm", "chute.length",
       "must be >= 0.1 m"},
      {"design cases/pilot_hopper.toml --set hopper.slot_length=1e308m", "hopper.slot_length",
       "<= 50 m"},
      {"design cases/rotating_drum_20rpm.toml --set 'drum.length=1e-300 mm'", "drum.length",
       ">= 10 mm"},
      {"design cases/pilot_hopper.toml --set material.hypoplastic.e_i0=1e308",
       "material.hypoplastic.e_i0", "<= 10"},
      {"design cases/pilot_hopper.toml --set hopper.semi_angle=89.9deg", "hopper.semi_angle",
       "<= 80 deg"},
      {"design cases/pilot_hopper.toml --set 'material.bulk.loose_density=400 kg/m^3'",
       "material.bulk.loose_density", "must not exceed the design density (290 kg/m^3)"},
      {"design cases/pilot_hopper.toml --set hopper.slot_length=1mm", "hopper.slot_length",
       "at least the outlet width (60 mm)"},
      {"design cases/rotating_drum_20rpm.toml --set drum.diameter=1mm", "drum.diameter",
       ">= 10 mm"},
      {"design cases/rotating_drum_20rpm.toml --set drum.diameter=12mm --set "
       "material.psd.d50=1.5mm",
       "drum.diameter", "at least 10 median grain sizes (15 mm"},
      {"design cases/pilot_hopper.toml --set dem.random_seed=1.5", "dem.random_seed",
       "a whole number"},
      {"simulate cases/rotating_drum_20rpm.toml --solver dem --set dem.time_step_safety=2 --time "
       "0.02s",
       "dem.time_step_safety", "<= 1, got 2 (fraction of the stable step"},
      {"simulate cases/pilot_hopper.toml --solver cel --set cel.time_step_safety=1.5 --time 0.02s",
       "cel.time_step_safety", "above 1 a wave crosses more than a cell per step"},
      {"simulate cases/rotating_drum_20rpm.toml --solver dem --set dem.time_step_safety=0.5 --set "
       "dem.time_step=1us "
       "--time 0.02s",
       "dem.time_step_safety", "not both"},
      {"design cases/inclined_plane_29_5.toml --set chute.bin_length=31m", "chute.bin_length",
       "<= 5000 mm"},
      {"design cases/inclined_plane_29_5.toml --set chute.gate_opening=0.35mm",
       "chute.gate_opening", ">= 10 mm"},
      {"simulate cases/rotating_drum_20rpm.toml --solver dem --set dem.slab_depth=1e9m --time "
       "0.02s",
       "dem.slab_depth", "<= 1000 mm"},
      {"simulate cases/pilot_hopper.toml --solver cel --set cel.cell_size=1um", "cel.cell_size",
       ">= 1 mm"},
      {"simulate cases/pilot_hopper.toml --solver dem --set dem.normal_law=hertz --set "
       "dem.cohesion=k_nc",
       "dem.cohesion",
       "use it with normal_law hysteretic_nonlinear2 or hysteretic_nonlinear1, not hertz"},
      {"simulate cases/pilot_hopper.toml --solver dem --set dem.cohesion=glue", "dem.cohesion",
       "k_nc"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.command);
    const auto start = std::chrono::steady_clock::now();
    const auto r = run_feedflow(std::string(c.command) + " --out o", dir_);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(std::string("--set: ") + c.names + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.range), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "o"));
    EXPECT_LT(seconds, 20.0) << "refused only after the work";
  }
}

// A 100 kB value is not echoed whole: the message stays short and still names the key.
TEST_F(InputRanges, HugeValueIsCutInTheMessage) {
  const auto r = run_feedflow("design cases/pilot_hopper.toml --set hopper.semi_angle=" + std::string(100000, 'a'),
                              dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set: hopper.semi_angle: "), std::string::npos) << r.err.substr(0, 300);
  EXPECT_NE(r.err.find("...(100002 characters)"), std::string::npos) << r.err.substr(0, 300);
  EXPECT_LT(r.err.size(), 1000u);
}

// A case file named without a folder ("wedge.toml" in its own folder) finds its own materials/.
TEST_F(InputRanges, CaseWithoutFolderFindsItsOwnMaterials) {
  std::string material = slurp(dir_ / "cases/materials/loblolly_pine.toml");
  const std::string density = "density = { value = \"290 kg/m^3\"";
  material.replace(material.find(density), density.size(), "density = { value = \"280 kg/m^3\"");
  fs::create_directories(dir_ / "mine/materials");
  std::ofstream(dir_ / "mine/materials/loblolly_pine.toml") << material;
  fs::copy_file(dir_ / "cases/pilot_hopper.toml", dir_ / "mine/wedge.toml");
  const auto r = run_feedflow("design wedge.toml --json -", dir_ / "mine");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json.at("inputs").at("material").at("bulk").at("density").get<double>(), 280.0);
}

// A case-local material entry that is a folder, a link loop or a file naming another material is
// an error naming it, not a silent fall-back on the built-in material of that name.
TEST_F(InputRanges, BrokenCaseLocalMaterialIsAnError) {
  fs::create_directories(dir_ / "mine/materials");
  fs::copy_file(dir_ / "cases/pilot_hopper.toml", dir_ / "mine/wedge.toml");
  const fs::path entry = dir_ / "mine/materials/loblolly_pine.toml";
  const auto expect_refused = [&](const char* what) {
    SCOPED_TRACE(what);
    const auto r = run_feedflow("design wedge.toml --out o", dir_ / "mine");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("materials/loblolly_pine.toml"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "mine/o"));
  };
  fs::create_directories(entry);
  expect_refused("is a folder");
  fs::remove(entry);
  fs::create_symlink("loop.toml", entry);
  fs::create_symlink("loblolly_pine.toml", dir_ / "mine/materials/loop.toml");
  expect_refused("leads nowhere");
  fs::remove(entry);
  std::string material = slurp(dir_ / "cases/materials/loblolly_pine.toml");
  material.replace(material.find("name = \"loblolly_pine\""), 22, "name = \"oak\"");
  std::ofstream(entry) << material;
  expect_refused("declares the material \"oak\"");
}

// "no material named X" says where it looked.
TEST_F(InputRanges, UnknownMaterialSaysWhereItLooked) {
  const auto r = run_feedflow("design cases/pilot_hopper.toml --set case.material=oak", dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no material named \"oak\" in cases/materials/ or the built-in materials"),
            std::string::npos)
      << r.err;
}

// A key nested a hundred thousand levels deep is refused (toml++ would overflow its stack).
TEST_F(InputRanges, DeepKeysAreRefusedNotACrash) {
  std::string text = slurp(dir_ / "cases/pilot_hopper.toml") + "\n[hopper";
  for (int i = 0; i < 100000; ++i) text += ".x";
  std::ofstream(dir_ / "cases/deep.toml") << text << "]\n";
  const auto r = run_feedflow("design cases/deep.toml", dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cases/deep.toml:"), std::string::npos) << r.err.substr(0, 300);
  EXPECT_NE(r.err.find("nested over"), std::string::npos) << r.err.substr(0, 300);
}

}  // namespace
