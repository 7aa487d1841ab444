// The drum's flowing-layer calibration (designer/calibrate/drum_layer_fit, drum_calibration_design,
// calibration_toml; designer/case/calibration_reader; designer/design/drum_check): the fit
// recovers the coefficients that made its data, holds c_delta that leaves its physical range,
// the [calibration.drum] table round-trips beside the hopper's [calibration] without touching
// it, the design check uses it and says so, and each design point is the bench's own question.
#include <gtest/gtest.h>

#include "pine_material.hpp"

#include "designer/bench/bench_plan.hpp"
#include "designer/bench/bench_run.hpp"
#include "designer/calibrate/calibration_toml.hpp"
#include "designer/calibrate/drum_calibration_design.hpp"
#include "designer/calibrate/drum_layer_fit.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/case/material_reader.hpp"
#include "designer/design/design_check.hpp"
#include "designer/design/drum_check.hpp"
#include "models/core/errors.hpp"
#include "models/material/builtin_materials.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

using testing::pine_text;

using testing::read_material_text;

Drum seed_drum(double rpm) {
  Drum d = std::get<Drum>(load_case("cases/rotating_drum_20rpm.toml").equipment);
  d.speed = rpm * kRpm;
  return d;
}

// Angles the layer gives with (c_delta, shift) and no end walls, as a slice's references.
std::vector<DrumObservation> made_by(double fraction, double shift, const std::vector<double>& rpms,
                                     const std::vector<double>& held_out) {
  Material m = read_material_text(pine_text());
  m.drum_flow->end_wall_friction = 0.0;
  m.calibration.emplace().drum.emplace().layer.coefficients = {{"layer_fraction", fraction},
                                                               {"friction_shift", shift}};
  std::vector<DrumObservation> out;
  for (double rpm : rpms)
    out.push_back(
        {seed_drum(rpm), rolling_angle_band(seed_drum(rpm), m).nominal, 1 * kDegree, false});
  for (double rpm : held_out)
    out.push_back(
        {seed_drum(rpm), rolling_angle_band(seed_drum(rpm), m).nominal, 1 * kDegree, true});
  return out;
}

DrumCalibration drum_example(double fraction, double shift) {
  DrumCalibration c;
  c.against = "cel";
  c.rung = "L2 CEL-FEM, cells 20, 10 and 5 mm";
  c.scene = "rotating_drum_20rpm";
  c.commit = "0123456789";
  c.date = "2026-12-06";
  c.layer.coefficients = {{"layer_fraction", fraction}, {"friction_shift", shift}};
  c.layer.figures = {{"fit_rms_error", "2 %"}, {"held_out_max_error", "5 %"}};
  c.points = 1;
  c.diameter = 0.145;
  c.fill_fraction = 0.5;
  return c;
}

const std::vector<DrumPointRecord> kDrumPoints = {
    {10 * kRpm, 50 * kDegree, 8 * kDegree, false, "CEL Richardson"}};

// Synthetic angles from c_delta 0.3 and +6 deg over 5-30 rpm: the fit returns both (the
// published 0.2 and 0 deg are its start), and the held-out speed is met to the fit's precision.
TEST(DrumLayerFit, RecoversTheCoefficientsThatMadeItsData) {
  const auto obs = made_by(0.3, 6 * kDegree, {5, 10, 20, 30}, {25});
  const DrumLayerFit f = fit_drum_layer(obs, read_material_text(pine_text()), false);
  ASSERT_TRUE(f.failure.empty()) << f.failure;
  EXPECT_NEAR(f.layer_fraction_after, 0.3, 1e-4);
  EXPECT_NEAR(in_degrees(f.shift_after), 6.0, 1e-3);
  EXPECT_LT(f.held_out_max_after, 1e-5);
  EXPECT_GT(f.fit_rms_before, 0.05);  // the published layer was 6 deg of friction off
  EXPECT_TRUE(f.held.empty());
  for (bool holds : f.band_holds_after) EXPECT_TRUE(holds);
}

// Data a layer of 0.02 of the half-chord made (saturated at mu_2: 40.0 deg at every speed): the
// fit would take c_delta below 0.05, so it is held at the material's 0.2 and the shift alone is
// fitted (the held figure says so).
TEST(DrumLayerFit, HoldsALayerFractionOutsideItsRange) {
  const auto obs = made_by(0.02, 0.0, {5, 10, 20, 30}, {});
  const DrumLayerFit f = fit_drum_layer(obs, read_material_text(pine_text()), false);
  ASSERT_TRUE(f.failure.empty()) << f.failure;
  EXPECT_DOUBLE_EQ(f.layer_fraction_after, 0.2);
  EXPECT_NE(f.held.find("c_delta held at 0.2"), std::string::npos) << f.held;
  EXPECT_EQ(f.layer.figures.count("held_1"), 1u);
  EXPECT_LT(f.fit_rms_after, f.fit_rms_before);
}

// Written beside a hopper calibration and read back: the drum's coefficients (the shift in
// degrees in the file), the hopper's part untouched; a second drum calibration replaces the first.
TEST(DrumCalibrationToml, RoundTripsBesideTheHoppersCalibration) {
  Calibration hopper;
  hopper.against = "cel";
  hopper.rung = "L2 CEL-FEM";
  hopper.scene = "pilot_hopper";
  hopper.geometry = "wedge";
  hopper.density_model = "compressible";
  hopper.commit = "abc";
  hopper.date = "2026-12-02";
  hopper.discharge["johanson"].coefficients = {{"factor", 1.83}};
  const std::string with_hopper =
      with_calibration(pine_text(), calibration_toml(hopper, {}), CalibrationPart::hopper);
  const std::string both = with_calibration(
      with_hopper, drum_calibration_toml(drum_example(0.31, 4.5 * kDegree), kDrumPoints),
      CalibrationPart::drum);
  EXPECT_NE(both.find("friction_shift = \"4.5 deg\""), std::string::npos) << both;
  const Material m = read_material_text(both);
  ASSERT_TRUE(m.calibration && m.calibration->drum);
  EXPECT_DOUBLE_EQ(m.calibration->drum->layer.coefficients.at("layer_fraction"), 0.31);
  EXPECT_NEAR(m.calibration->drum->layer.coefficients.at("friction_shift"), 4.5 * kDegree, 1e-15);
  EXPECT_EQ(m.calibration->drum->points, 1u);
  EXPECT_DOUBLE_EQ(*m.calibration->drum->diameter, 0.145);
  EXPECT_DOUBLE_EQ(*m.calibration->drum->fill_fraction, 0.5);
  EXPECT_DOUBLE_EQ(m.calibration->discharge.at("johanson").coefficients.at("factor"), 1.83);

  const std::string again = with_calibration(
      both, drum_calibration_toml(drum_example(0.25, -2 * kDegree), {}), CalibrationPart::drum);
  const Material m2 = read_material_text(again);
  EXPECT_DOUBLE_EQ(m2.calibration->drum->layer.coefficients.at("layer_fraction"), 0.25);
  EXPECT_EQ(m2.calibration->drum->points, 0u);
  EXPECT_DOUBLE_EQ(m2.calibration->discharge.at("johanson").coefficients.at("factor"), 1.83);
  // A hopper calibration written afterwards keeps the drum's part.
  const Material m3 = read_material_text(
      with_calibration(again, calibration_toml(hopper, {}), CalibrationPart::hopper));
  EXPECT_DOUBLE_EQ(m3.calibration->drum->layer.coefficients.at("layer_fraction"), 0.25);
  // A drum calibration alone reads without the hopper's provenance.
  const Material alone = read_material_text(with_calibration(
      pine_text(), drum_calibration_toml(drum_example(0.3, 0.0), {}), CalibrationPart::drum));
  EXPECT_TRUE(alone.calibration->discharge.empty());
  EXPECT_DOUBLE_EQ(alone.calibration->drum->layer.coefficients.at("layer_fraction"), 0.3);
}

// c_delta outside (0, 1], a shift beyond 30 deg or without its unit's dimension: refused naming the
// key.
TEST(DrumCalibrationToml, BrokenCoefficientsAreRefusedNamingTheKey) {
  const auto key_of = [](const std::string& table) {
    try {
      read_material_text(pine_text() + "\n" + table);
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("accepted");
  };
  const std::string good = drum_calibration_toml(drum_example(0.31, 4.5 * kDegree), {});
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  EXPECT_EQ(key_of(good), "accepted");
  EXPECT_EQ(key_of(replaced("layer_fraction = 0.31", "layer_fraction = 1.5")),
            "calibration.drum.coefficients.layer_fraction");
  EXPECT_EQ(key_of(replaced("\"4.5 deg\"", "\"45 deg\"")),
            "calibration.drum.coefficients.friction_shift");
  EXPECT_EQ(key_of(replaced("\"4.5 deg\"", "\"4.5 mm\"")),
            "calibration.drum.coefficients.friction_shift");
  EXPECT_EQ(key_of(replaced("end_walls = false", "end_walls = \"no\"")),
            "calibration.drum.end_walls");
}

// The seed drum at 20 rpm: the calibrated layer moves the angle to the layer's value at the
// fitted coefficients (end walls kept: this drum has them), the model text and the assumptions
// name the calibration, and the band is widened by its largest error (5 %).
TEST(DrumCalibration, DesignUsesTheCalibrationAndSaysSo) {
  Case c = load_case("cases/rotating_drum_20rpm.toml");
  c.material = read_material_text(pine_text());
  const DesignRecord before = design_check(c);
  c.material = read_material_text(
      with_calibration(pine_text(), drum_calibration_toml(drum_example(0.31, 4.5 * kDegree), {}),
                       CalibrationPart::drum));
  const DesignRecord after = design_check(c);
  const Estimate& a0 = *find_estimate(before.results, "dynamic_angle_of_repose");
  const Estimate& a1 = *find_estimate(after.results, "dynamic_angle_of_repose");
  const double expected =
      in_degrees(rolling_angle_band(std::get<Drum>(c.equipment), c.material).nominal);
  EXPECT_NEAR(std::get<double>(a1.value), expected, 1e-9);
  EXPECT_GT(std::get<double>(a1.value), std::get<double>(a0.value) + 2.0);  // 4.5 deg more friction
  EXPECT_NE(a1.model.find("calibrated (c_delta 0.31"), std::string::npos) << a1.model;
  EXPECT_LE(*a1.low, 0.95 * std::get<double>(a1.value) + 1e-9);
  EXPECT_GE(*a1.high, 1.05 * std::get<double>(a1.value) - 1e-9);
  bool said = false, published = false;
  for (const auto& a : after.assumptions)
    said = said || a.find("[calibration.drum]") != std::string::npos;
  for (const auto& a : before.assumptions)
    published = published || a.find("not calibrated") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_TRUE(published);
  // The calibrated drum itself is not an extrapolation; a 1 m drum at 30 % fill is, and says so.
  const auto extrapolated = [](const DesignRecord& r) {
    for (const auto& a : r.assumptions)
      if (a.find("outside the calibrated one") != std::string::npos) return a;
    return std::string();
  };
  EXPECT_EQ(extrapolated(after), "");
  std::get<Drum>(c.equipment).diameter = 1.0;
  std::get<Drum>(c.equipment).fill_fraction = 0.3;
  EXPECT_NE(extrapolated(design_check(c))
                .find("(diameter 1000 mm against 145 mm, fill 30 % against 50 %)"),
            std::string::npos)
      << extrapolated(design_check(c));
}

// A design point at 10 rpm is the bench's drum_angle_10rpm question on the CEL levels 20-5 mm:
// the same run folders and invocations, so the bench's runs are read back.
TEST(DrumCalibrationDesign, APointIsTheBenchsQuestion) {
  DrumCalibrationDesign d;
  d.case_file = "cases/rotating_drum_20rpm.toml";
  d.points = speed_points({10 * kRpm, 20 * kRpm}, {15 * kRpm});
  d.check();
  const BenchQuestion q = drum_point_question(d, d.points.front());
  const BenchQuestion bench = drum_question("10", false);
  ASSERT_EQ(q.points.size(), 3u);
  for (const auto& p : q.points) {
    const auto same = std::find_if(bench.points.begin(), bench.points.end(),
                                   [&](const BenchPoint& b) { return b.setting == p.setting; });
    ASSERT_NE(same, bench.points.end()) << p.setting;
    EXPECT_EQ(bench_run_folder("runs", q, p), bench_run_folder("runs", bench, *same));
    EXPECT_EQ(bench_invocation(q, p), bench_invocation(bench, *same));
    EXPECT_EQ(p.role, ReferenceRole::cel_refinement);
  }
  EXPECT_EQ(drum_point_question(d, d.points.back()).id, "drum_angle_15rpm");
  d.against = "dem";
  const BenchQuestion dem = drum_point_question(d, d.points.front());
  ASSERT_EQ(dem.points.size(), 1u);
  EXPECT_EQ(dem.points.front().role, ReferenceRole::dem_reference);
  // One fitted speed cannot fit two coefficients.
  d.points = speed_points({10 * kRpm}, {15 * kRpm});
  EXPECT_THROW(d.check(), InputError);
}

}  // namespace
}  // namespace feedflow
