// Case files: the shipped cases load with the right SI values; bad files are refused with the
// file, line and key named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "designer/case/case_loader.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

const char* kGoodHopper = R"([case]
name = "t"
description = "test hopper"

[hopper]
shape = "wedge"
semi_angle = "30 deg"
outlet_width = "60 mm"
fill_height = "0.68 m"
bin_width = "0.6 m"
slot_length = "0.5 m"
)";

class TempCase : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("feedflow_case_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& text, const std::string& name = "case.toml") {
    const auto path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  // Loads and returns the InputError message; fails the test if loading succeeds.
  std::string error_of(const std::string& text, std::vector<SetOverride> overrides = {}) {
    const auto path = write(text);
    try {
      load_case(path, overrides);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return "";
  }

  fs::path dir_;
};

// The seed's pilot hopper resolves to the SI values the case file states in units.
TEST_F(TempCase, PilotHopperLoadsInSi) {
  const Case c = load_case("cases/pilot_hopper.toml");
  ASSERT_EQ(c.kind(), EquipmentKind::hopper);
  const auto& h = std::get<Hopper>(c.equipment);
  EXPECT_EQ(h.shape, "wedge");
  EXPECT_NEAR(h.semi_angle, 30 * kDegree, 1e-12);
  EXPECT_NEAR(h.outlet_width, 0.060, 1e-12);
  EXPECT_NEAR(h.fill_height, 0.68, 1e-12);
  EXPECT_NEAR(h.bin_width, 0.6, 1e-12);
  EXPECT_NEAR(*h.wall_friction_angle, 8.5 * kDegree, 1e-12);
  EXPECT_EQ(c.material.name, "loblolly_pine");
  EXPECT_NEAR(c.material.bulk.density, 290.0, 1e-12);
  EXPECT_NEAR(c.design.outlet_safety_factor, 1.2, 1e-12);
  EXPECT_TRUE(c.warnings.empty());
}

// Every shipped case file loads without error and has a description for `feedflow cases`.
TEST_F(TempCase, EveryShippedCaseLoads) {
  int count = 0;
  for (const auto& item : fs::directory_iterator("cases")) {
    if (item.path().extension() != ".toml") continue;
    SCOPED_TRACE(item.path().string());
    const Case c = load_case(item.path().string());
    EXPECT_FALSE(c.description.empty());
    ++count;
  }
  EXPECT_EQ(count, 6);
}

// A case loaded with overrides says so after its own words, which describe the file's values
// ("60 mm slot"), not the ones set over them.
TEST_F(TempCase, OverridesFollowTheDescription) {
  const Case c = load_case(
      "cases/pilot_hopper.toml",
      std::vector<SetOverride>{{"hopper.outlet_width", "45mm"}, {"hopper.fill_height", "0.35m"}});
  EXPECT_TRUE(c.description.starts_with(load_case("cases/pilot_hopper.toml").description + "; "));
  EXPECT_TRUE(
      c.description.ends_with("as changed: hopper.outlet_width = 45mm, hopper.fill_height = 0.35m"))
      << c.description;
}

// The inclined planes and the drum carry the seed's geometry in SI.
TEST_F(TempCase, ChuteAndDrumCasesInSi) {
  const auto chute = std::get<Chute>(load_case("cases/inclined_plane_37.toml").equipment);
  EXPECT_NEAR(chute.angle, 37 * kDegree, 1e-12);
  EXPECT_NEAR(chute.width, 0.76, 1e-12);
  EXPECT_NEAR(chute.bin_length, 0.57, 1e-12);
  EXPECT_NEAR(chute.bin_height, 0.915, 1e-12);
  EXPECT_GE(chute.gate_opening, 0.08);  // seed range at 37 deg: 8-19 cm
  EXPECT_LE(chute.gate_opening, 0.19);
  const auto drum = std::get<Drum>(load_case("cases/rotating_drum_20rpm.toml").equipment);
  EXPECT_NEAR(drum.diameter, 0.145, 1e-12);
  EXPECT_NEAR(drum.length, 0.202, 1e-12);
  EXPECT_NEAR(drum.fill_fraction, 0.5, 1e-12);
  EXPECT_NEAR(drum.speed, 20 * 2 * std::numbers::pi / 60, 1e-12);
}

// A misspelt key is refused with file, line, dotted key and a suggestion.
TEST_F(TempCase, TypoKeyNamesFileLineKeyAndSuggestion) {
  std::string text = kGoodHopper;
  text.replace(text.find("semi_angle"), 10, "semi_angel");
  const std::string m = error_of(text);
  EXPECT_NE(m.find("case.toml:7"), std::string::npos) << m;
  EXPECT_NE(m.find("hopper.semi_angel"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean \"semi_angle\""), std::string::npos) << m;
}

// A length given for an angle is a dimension error at its line.
TEST_F(TempCase, WrongUnitNamesDimension) {
  std::string text = kGoodHopper;
  text.replace(text.find("\"30 deg\""), 8, "\"30 mm\"");
  const std::string m = error_of(text);
  EXPECT_NE(m.find("case.toml:7"), std::string::npos) << m;
  EXPECT_NE(m.find("hopper.semi_angle"), std::string::npos) << m;
  EXPECT_NE(m.find("angle"), std::string::npos) << m;
  EXPECT_NE(m.find("length"), std::string::npos) << m;
}

// Out-of-range values are refused with the allowed range in the field's unit.
TEST_F(TempCase, OutOfRangeValuesAreRefused) {
  struct Bad { const char* from; const char* to; const char* key; const char* expect; };
  const Bad bad[] = {
      {"\"30 deg\"", "\"90 deg\"", "hopper.semi_angle", "<= 80 deg"},
      {"\"60 mm\"", "\"-60 mm\"", "hopper.outlet_width", "> 0 mm"},
      {"\"0.6 m\"", "\"0.05 m\"", "hopper.outlet_width", "smaller than bin_width"},
      {"\"wedge\"", "\"pyramid\"", "hopper.shape", "\"wedge\", \"conical\""},
      {"\"0.68 m\"", "\"0.05 m\"", "hopper.fill_height", "above the outlet"},
  };
  for (const auto& b : bad) {
    SCOPED_TRACE(b.key);
    std::string text = kGoodHopper;
    text.replace(text.find(b.from), std::string(b.from).size(), b.to);
    const std::string m = error_of(text);
    EXPECT_NE(m.find(b.key), std::string::npos) << m;
    EXPECT_NE(m.find(b.expect), std::string::npos) << m;
    EXPECT_NE(m.find("case.toml:"), std::string::npos) << m;
  }
}

// A drum filled over 100 % is refused; "50 %" is read as 0.5.
TEST_F(TempCase, DrumFillFractionRange) {
  const std::string drum = "[drum]\ndiameter = \"145 mm\"\nlength = \"202 mm\"\n"
                           "fill_fraction = \"120 %\"\nspeed = \"20 rpm\"\n";
  const std::string m = error_of(drum);
  EXPECT_NE(m.find("drum.fill_fraction"), std::string::npos) << m;
  EXPECT_NE(m.find("< 100%"), std::string::npos) << m;
}

// Missing required keys and missing equipment tables are named.
TEST_F(TempCase, MissingKeysAreNamed) {
  std::string text = kGoodHopper;
  text.erase(text.find("outlet_width"), std::string("outlet_width = \"60 mm\"\n").size());
  EXPECT_NE(error_of(text).find("hopper.outlet_width: missing"), std::string::npos);
  EXPECT_NE(error_of("[case]\nname = \"x\"\n").find("[hopper], [chute] or [drum]"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(kGoodHopper) + "[drum]\ndiameter = 1\n").find("both"),
            std::string::npos);
}

// Broken TOML is reported with its line, not a crash.
TEST_F(TempCase, SyntaxErrorNamesLine) {
  const std::string m = error_of("[hopper]\nshape = \"wedge\nsemi_angle = 3\n");
  EXPECT_NE(m.find("case.toml:2"), std::string::npos) << m;
  EXPECT_NE(m.find("not valid TOML"), std::string::npos) << m;
}

// --set overrides any field with units, and its errors say "--set".
TEST_F(TempCase, SetOverridesWithUnits) {
  const auto path = write(kGoodHopper);
  const Case c = load_case(path, std::vector<SetOverride>{{"hopper.semi_angle", "32deg"},
                                                          {"hopper.shape", "wedge"},
                                                          {"design.required_throughput", "5 t/h"}});
  EXPECT_NEAR(std::get<Hopper>(c.equipment).semi_angle, 32 * kDegree, 1e-12);
  EXPECT_NEAR(*c.design.required_throughput, 5000.0 / 3600.0, 1e-12);
  const std::string m = error_of(kGoodHopper, {{"hopper.semi_angle", "32 mm"}});
  EXPECT_EQ(m.rfind("--set: hopper.semi_angle:", 0), 0u) << m;
  EXPECT_NE(error_of(kGoodHopper, {{"hopper.semi_angel", "3"}}).find("did you mean"),
            std::string::npos);
  EXPECT_THROW(parse_set_override("no_equals_sign"), InputError);
}

// --set and a [material] table override the named material; sources say where values came from.
TEST_F(TempCase, MaterialOverrides) {
  const auto path = write(std::string(kGoodHopper) + "\n[material.bulk]\ndensity = \"250 kg/m^3\"\n");
  const Case c = load_case(path, std::vector<SetOverride>{{"material.psd.d50", "1 mm"}});
  EXPECT_NEAR(c.material.bulk.density, 250.0, 1e-12);
  EXPECT_NEAR(c.material.psd->d50, 1e-3, 1e-15);
  EXPECT_NEAR(c.material.bulk.loose_density.value(), 182.0, 1e-12);  // untouched: from the base
  EXPECT_NE(c.material.sources.at("bulk.density").find(path), std::string::npos);
  EXPECT_EQ(c.material.sources.at("psd.d50"), "command line (--set)");
  EXPECT_NE(c.material.sources.at("hypoplastic.phi_c").find("Table 1"), std::string::npos);
  // The hopper's wall friction defaults to the material's.
  EXPECT_NEAR(*std::get<Hopper>(c.equipment).wall_friction_angle, 8.5 * kDegree, 1e-12);
}

// An unknown material name is refused naming case.material and the known materials.
TEST_F(TempCase, UnknownMaterialIsNamed) {
  const std::string m = error_of("[case]\nmaterial = \"oak\"\n" +
                                   std::string(kGoodHopper).substr(std::string(kGoodHopper).find("[hopper]")));
  EXPECT_NE(m.find("case.material"), std::string::npos) << m;
  EXPECT_NE(m.find("loblolly_pine"), std::string::npos) << m;
}

// A target of another kind of equipment is refused; a short slot is accepted with a warning.
TEST_F(TempCase, DesignTargetsBelongToTheirEquipment) {
  EXPECT_NE(error_of(std::string(kGoodHopper) + "[design]\nmax_stopping_thickness = \"5 mm\"\n")
                .find("is a chute target"),
            std::string::npos);
  std::string text = kGoodHopper;
  text.replace(text.find("\"0.5 m\""), 7, "\"0.1 m\"");
  const Case c = load_case(write(text));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("slot_length"), std::string::npos);
}

}  // namespace
}  // namespace feedflow

namespace feedflow {
namespace {

// A case may define its own complete material in [material] (with a name, no case.material).
TEST_F(TempCase, StandaloneMaterialInCase) {
  const std::string text = std::string(kGoodHopper) +
                           "[material]\nname = \"sawdust\"\ndescription = \"test\"\n"
                           "[material.bulk]\ndensity = \"200 kg/m^3\"\nwall_friction_angle = \"20 deg\"\n";
  const Case c = load_case(write(text));
  EXPECT_EQ(c.material.name, "sawdust");
  EXPECT_NEAR(c.material.bulk.density, 200.0, 1e-12);
  EXPECT_FALSE(c.material.hypoplastic.has_value());
  EXPECT_NEAR(*std::get<Hopper>(c.equipment).wall_friction_angle, 20 * kDegree, 1e-12);
  // Incomplete: the bulk section's required keys are named.
  const std::string m = error_of(std::string(kGoodHopper) + "[material]\nname = \"x\"\n[material.bulk]\ndensity = 1\n");
  EXPECT_NE(m.find("material.bulk.wall_friction_angle: missing"), std::string::npos) << m;
}

}  // namespace
}  // namespace feedflow

namespace feedflow {
namespace {

template <class Record>
void expect_lengths_bounded(std::span<const FieldSpec<Record>> fields, const char* table) {
  for (const auto& f : fields)
    if (!f.is_label() && f.dimension == dim::length) {
      EXPECT_TRUE(std::isfinite(f.range.upper) && f.range.upper < 1e3) << table << "." << f.key;
    }
}

// Every length a case or a material gives has a finite upper bound (a 1e308 m slot or a 1e9 m
// slab is refused at input, not met by a model or a run that never ends).
TEST(InputRangesTable, EveryLengthHasAnUpperBound) {
  expect_lengths_bounded(hopper_fields(), "hopper");
  expect_lengths_bounded(chute_fields(), "chute");
  expect_lengths_bounded(drum_fields(), "drum");
  expect_lengths_bounded(psd_fields(), "psd");
  expect_lengths_bounded(dem_particle_fields(), "dem.particle");
  expect_lengths_bounded(surface_flow_fields(), "surface_flow");
  expect_lengths_bounded(design_target_fields(), "design");
  expect_lengths_bounded(dem_case_fields(), "dem");
  expect_lengths_bounded(cel_case_fields(), "cel");
}

}  // namespace
}  // namespace feedflow
