// The arching calibration (designer/calibrate/arching_fit, arching_records, calibration_toml;
// designer/case/calibration_reader; models/hopper/hopper_evaluation): the fit recovers the
// strength scale that made its brackets and predicts a held-out semi-angle, its scale range is
// where B_c leaves the bracket, a verified record reads into a bracket and is refused when it is
// not one, [calibration.arching] round-trips beside the other parts, and the design check's B_c
// follows the scale for the calibrated geometry only.
#include <gtest/gtest.h>

#include <fstream>

#include "pine_material.hpp"

#include "designer/calibrate/arching_fit.hpp"
#include "designer/calibrate/arching_records.hpp"
#include "designer/calibrate/calibration_toml.hpp"
#include "designer/case/case_loader.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

using testing::pine_text;

Hopper pilot_at(double degrees) {
  Hopper h = std::get<Hopper>(load_case("cases/pilot_hopper.toml").equipment);
  h.semi_angle = degrees * kDegree;
  return h;
}

// The row's B_c at the nominal material values with sigma_c times `scale`.
double width_with(double scale, const Hopper& h, const std::string& row = "envelope") {
  HopperMaterial m = HopperMaterial::of(testing::read_material_text(pine_text()));
  m.arching_calibration = ArchingScale{flow_geometry(h), "enstad", {{row, scale}}, "test"};
  HopperModels models;
  models.critical_outlet = &critical_outlet_models().at(row);
  return evaluate_hopper(h, h.semi_angle, h.outlet_width, m,
                         material_variants(m, *h.wall_friction_angle).front(), models)
      .critical_width;
}

const HopperMaterial& pine_arching() {
  static const HopperMaterial m = HopperMaterial::of(testing::read_material_text(pine_text()));
  return m;
}

// Brackets made by the default row (envelope) with sigma_c x 1.4 (B_c at the geometric middle of
// +-10 %) at 20 and 40 deg: the fit finds 1.4 for that row, and the held-out 30 deg point then
// sits on its reference where the published strength was more than 10 % off.
TEST(ArchingFit, RecoversTheStrengthThatMadeItsBrackets) {
  std::vector<ArchingObservation> obs;
  for (double deg : {20.0, 40.0, 30.0}) {
    const double w = width_with(1.4, pilot_at(deg));
    obs.push_back({pilot_at(deg), w / 1.1, w * 1.1, deg == 30.0});
  }
  const auto fits = fit_arching(obs, pine_arching());
  ASSERT_EQ(fits.size(), critical_outlet_models().rows.size());
  const ArchingRowFit& f = fits.front();
  ASSERT_EQ(f.row, &critical_outlet_models().default_row());
  EXPECT_NEAR(f.scale, 1.4, 1e-6);
  EXPECT_LT(f.fit_rms_after, 1e-6);
  EXPECT_LT(f.held_out_max_after, 1e-6);
  EXPECT_GT(f.held_out_max_before, 0.1);
  EXPECT_EQ(f.held_before, 0u);
  EXPECT_EQ(f.held_after, 3u);
  EXPECT_LT(f.scale_low, 1.4);
  EXPECT_GT(f.scale_high, 1.4);
}

// With one bracket the scale range ends where the row's B_c meets the bracket's ends: the
// narrowest outlet seen to arch at scale_low, the widest seen to flow at scale_high.
TEST(ArchingFit, TheScaleRangeEndsWhereBcLeavesTheBracket) {
  const Hopper h = pilot_at(30.0);
  const std::vector<ArchingObservation> obs{{h, 0.03133, 0.04218, false}};
  for (const auto& f : fit_arching(obs, pine_arching())) {
    const std::string row(f.row->name);
    EXPECT_NEAR(width_with(f.scale_low, h, row), 0.03133, 1e-8) << row;
    EXPECT_NEAR(width_with(f.scale_high, h, row), 0.04218, 1e-8) << row;
    EXPECT_NEAR(width_with(f.scale, h, row), std::sqrt(0.03133 * 0.04218), 1e-8) << row;
  }
}

// A bracket that flows below where it arches, or points of two geometries, are refused.
TEST(ArchingFit, RefusesWhatIsNoBracket) {
  EXPECT_THROW(fit_arching({{pilot_at(30.0), 0.04, 0.03, false}}, pine_arching()),
               std::invalid_argument);
  Hopper cone = pilot_at(30.0);
  cone.shape = "conical";
  EXPECT_THROW(
      fit_arching({{pilot_at(30.0), 0.03, 0.04, false}, {cone, 0.03, 0.04, false}}, pine_arching()),
      std::invalid_argument);
  EXPECT_THROW(fit_arching({{pilot_at(30.0), 0.03, 0.04, true}}, pine_arching()),
               std::invalid_argument);
}

const std::filesystem::path kRecord =
    std::filesystem::path(FEEDFLOW_TEST_DATA_DIR) / "verified_bc" / "pilot_hopper_30deg_k_nc.json";

// The pilot hopper's record (tests/data/verified_bc): 30 deg, 8.5 deg walls, the DEM bracket
// 31.33-42.18 mm, the rung in words; asked for the continuum rung or another material, refused
// naming the key.
TEST(ArchingRecords, AVerifiedDesignReadsIntoItsBracket) {
  const Hopper h = pilot_at(20.0);
  const ArchingRecord r = read_arching_record(kRecord, "dem", "loblolly_pine", h);
  EXPECT_NEAR(in_degrees(r.observation.hopper.semi_angle), 30.0, 1e-12);
  EXPECT_NEAR(in_degrees(*r.observation.hopper.wall_friction_angle), 8.5, 1e-12);
  EXPECT_NEAR(r.observation.arches_at, 0.031326, 1e-6);
  EXPECT_NEAR(r.observation.flows_at, 0.042176, 1e-6);
  EXPECT_EQ(r.rung, "L3 DEM (hysteretic_nonlinear2 + k_nc cohesion)");
  EXPECT_EQ(r.bracket, "arches at 31.33 mm, flows at 42.18 mm");
  try {
    read_arching_record(kRecord, "cel", "loblolly_pine", h);
    ADD_FAILURE() << "a DEM record passed for the continuum rung";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("results.critical_outlet_width.rung"), std::string::npos)
        << e.what();
  }
  try {
    read_arching_record(kRecord, "dem", "douglas_fir", h);
    ADD_FAILURE() << "another material's record passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("input_display.material.name"), std::string::npos)
        << e.what();
  }
  Hopper cone = h;
  cone.shape = "conical";
  EXPECT_THROW(read_arching_record(kRecord, "dem", "loblolly_pine", cone), InputError);
}

ArchingCalibration arching_example(double scale) {
  ArchingCalibration a;
  a.against = "dem";
  a.rung = "L3 DEM (hysteretic_nonlinear2 + k_nc cohesion)";
  a.scene = "pilot_hopper";
  a.geometry = "wedge";
  a.flow_factor = "enstad";
  a.commit = "abc";
  a.date = "2026-12-07";
  a.rows["envelope"].coefficients["strength_scale"] = scale;
  a.rows["envelope"].figures["scale_range"] = "1.02 .. 1.32";
  a.points = 1;
  return a;
}

// [calibration.arching] reads back as written, beside the discharge part the pine ships with;
// writing it again replaces it and keeps the discharge part; written alone it needs no hopper
// provenance.
TEST(ArchingCalibrationToml, RoundTripsBesideTheDischargeCalibration) {
  const std::string discharge_part =
      "[calibration]\nagainst = \"cel\"\nrung = \"L2\"\nscene = \"s\"\ngeometry = \"wedge\"\n"
      "density_model = \"compressible\"\ncommit = \"c\"\ndate = \"d\"\n"
      "[calibration.discharge.johanson]\ncoefficients = { factor = 1.83 }\n";
  const std::string point_text =
      arching_calibration_toml(arching_example(1.1626858527697574),
                               {{30 * kDegree, 8.5 * kDegree, 0.03133, 0.04218, false, "record"}});
  std::string text =
      with_calibration(with_calibration(pine_text(), discharge_part, CalibrationPart::hopper),
                       point_text, CalibrationPart::arching);
  const Material m = testing::read_material_text(text);
  ASSERT_TRUE(m.calibration && m.calibration->arching);
  EXPECT_DOUBLE_EQ(m.calibration->arching->rows.at("envelope").coefficients.at("strength_scale"),
                   1.1626858527697574);
  EXPECT_EQ(m.calibration->arching->rows.at("envelope").figures.at("scale_range"), "1.02 .. 1.32");
  EXPECT_EQ(m.calibration->arching->points, 1u);
  EXPECT_EQ(m.calibration->arching->flow_factor, "enstad");
  EXPECT_DOUBLE_EQ(m.calibration->discharge.at("johanson").coefficients.at("factor"), 1.83);
  text = with_calibration(text, arching_calibration_toml(arching_example(0.9), {}),
                          CalibrationPart::arching);
  const Material again = testing::read_material_text(text);
  EXPECT_DOUBLE_EQ(
      again.calibration->arching->rows.at("envelope").coefficients.at("strength_scale"), 0.9);
  EXPECT_EQ(again.calibration->arching->points, 0u);
  EXPECT_DOUBLE_EQ(again.calibration->discharge.at("johanson").coefficients.at("factor"), 1.83);
  const Material alone = testing::read_material_text(with_calibration(
      pine_text(), arching_calibration_toml(arching_example(1.2), {}), CalibrationPart::arching));
  EXPECT_TRUE(alone.calibration->discharge.empty());
  EXPECT_DOUBLE_EQ(
      alone.calibration->arching->rows.at("envelope").coefficients.at("strength_scale"), 1.2);
}

// A scale out of [0.01, 100], an unknown row and an unknown flow-factor row are refused naming
// the key.
TEST(ArchingCalibrationToml, BrokenTablesAreRefusedNamingTheKey) {
  const std::string good = with_calibration(
      pine_text(), arching_calibration_toml(arching_example(1.2), {}), CalibrationPart::arching);
  const auto key_of = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    try {
      testing::read_material_text(text);
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(key_of("strength_scale = 1.2", "strength_scale = 0"),
            "calibration.arching.rows.envelope.coefficients.strength_scale");
  EXPECT_EQ(key_of("rows.envelope]", "rows.envelop]"), "calibration.arching.rows.envelop");
  EXPECT_EQ(key_of("flow_factor = \"enstad\"", "flow_factor = \"jenike\""),
            "calibration.arching.flow_factor");
}

// The design check's B_c follows the calibrated scale for wedges, and a cone keeps the measured
// flow function (the calibration was made on a wedge).
TEST(ArchingCalibration, DesignUsesItForTheCalibratedGeometryOnly) {
  Material m = testing::read_material_text(with_calibration(
      pine_text(), arching_calibration_toml(arching_example(1.2), {}), CalibrationPart::arching));
  const HopperMaterial calibrated = HopperMaterial::of(m);
  const Hopper wedge = pilot_at(30.0);
  const auto nominal = [&](const HopperMaterial& hm, const Hopper& h) {
    return evaluate_hopper(h, h.semi_angle, h.outlet_width, hm,
                           material_variants(hm, *h.wall_friction_angle).front());
  };
  const HopperEvaluation e = nominal(calibrated, wedge);
  EXPECT_NEAR(e.critical_width, width_with(1.2, wedge), 1e-12);
  EXPECT_GT(e.critical_width, nominal(pine_arching(), wedge).critical_width * 1.05);
  EXPECT_NE(e.critical_model.find("sigma_c x 1.2 calibrated against L3 DEM"), std::string::npos)
      << e.critical_model;
  Hopper cone = wedge;
  cone.shape = "conical";
  EXPECT_DOUBLE_EQ(nominal(calibrated, cone).critical_width,
                   nominal(pine_arching(), cone).critical_width);
}

}  // namespace
}  // namespace feedflow
