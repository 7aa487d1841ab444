// The chute's stopping-thickness calibration (designer/calibrate/stop_law_fit,
// chute_calibration_design, calibration_toml; designer/case/calibration_reader;
// designer/design/chute_check): the fit recovers the law that made its data, refuses deposits no
// Pouliquen law holds, a CEL level that cannot resolve the deposit it finds leaves the reference,
// the [calibration.chute] table round-trips beside the others, and the chute check uses it and
// says so.
#include <gtest/gtest.h>

#include <cmath>

#include "pine_material.hpp"

#include "designer/bench/bench_run.hpp"
#include "designer/calibrate/calibration_toml.hpp"
#include "designer/calibrate/chute_calibration_design.hpp"
#include "designer/calibrate/stop_law_fit.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/design/chute_check.hpp"
#include "designer/design/design_check.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

using testing::pine_text;

using testing::read_material_text;

// Pouliquen's h_stop, theta1 the pine's 27 deg unless given.
double h_stop(double theta2, double length, double angle, double theta1 = 27 * kDegree) {
  const double t1 = std::tan(theta1);
  return length * (std::tan(theta2) - std::tan(angle)) / (std::tan(angle) - t1);
}

std::vector<StopObservation> deposits_made_by(double theta2, double length,
                                              const std::vector<double>& fitted,
                                              const std::vector<double>& held_out,
                                              double theta1 = 27 * kDegree) {
  std::vector<StopObservation> out;
  // Each known to 2 % of itself.
  for (double deg : fitted) {
    const double h = h_stop(theta2, length, deg * kDegree, theta1);
    out.push_back({deg * kDegree, h, 0.02 * h, false});
  }
  for (double deg : held_out) {
    const double h = h_stop(theta2, length, deg * kDegree, theta1);
    out.push_back({deg * kDegree, h, 0.02 * h, true});
  }
  return out;
}

ChuteCalibration chute_example(double theta2, double length) {
  ChuteCalibration c;
  c.against = "dem";
  c.rung = "L3 DEM, the seed's law in periodic stopping layers (h_stop bisected to one sphere)";
  c.scene = "inclined_plane_29_5";
  c.lowest_angle = 29.5 * kDegree;
  c.highest_angle = 37 * kDegree;
  c.commit = "0123456789";
  c.date = "2026-12-07";
  c.law.coefficients = {{"theta2", theta2}, {"stop_length", length}};
  c.law.figures = {{"fit_rms_error", "3 %"}, {"held_out_max_error", "8 %"}};
  c.points = 3;
  return c;
}

// Deposits a law of theta1 = 25 deg, theta2 = 45 deg and L = 25 mm made at 29.5, 31, 33 and 37
// deg: the fit returns all three from the pine's published 27 deg, 40 deg and 10 mm, with a
// spare point for standard errors, and meets the held-out 35 deg.
TEST(StopLawFit, RecoversTheLawThatMadeItsData) {
  const auto obs = deposits_made_by(45 * kDegree, 25e-3, {29.5, 31, 33, 37}, {35}, 25 * kDegree);
  const StopLawFit f = fit_stop_law(obs, read_material_text(pine_text()));
  ASSERT_TRUE(f.failure.empty()) << f.failure;
  EXPECT_TRUE(f.theta1_fitted);
  EXPECT_DOUBLE_EQ(in_degrees(f.theta1_before), 27.0);
  EXPECT_NEAR(in_degrees(f.theta1_after), 25.0, 1e-4);
  EXPECT_NEAR(in_degrees(f.theta2_after), 45.0, 1e-4);
  EXPECT_NEAR(f.length_after * 1e3, 25.0, 1e-3);
  EXPECT_LT(f.held_out_max_after, 1e-5);
  EXPECT_GT(f.fit_rms_before, 0.3);  // the published law was far off
  EXPECT_TRUE(std::isfinite(f.theta1_error));
  EXPECT_TRUE(std::isfinite(f.theta2_error));
  EXPECT_EQ(f.law.coefficients.count("theta1"), 1u);
  for (bool holds : f.band_holds_after) EXPECT_TRUE(holds);
}

// Three inclinations determine theta1 too, exactly: no spare point, so no standard error.
TEST(StopLawFit, ThreeInclinationsFitTheta1Exactly) {
  const auto obs = deposits_made_by(44 * kDegree, 20e-3, {33, 37, 42}, {39.5}, 29 * kDegree);
  const StopLawFit f = fit_stop_law(obs, read_material_text(pine_text()));
  ASSERT_TRUE(f.failure.empty()) << f.failure;
  EXPECT_TRUE(f.theta1_fitted);
  EXPECT_NEAR(in_degrees(f.theta1_after), 29.0, 1e-3);
  EXPECT_NEAR(in_degrees(f.theta2_after), 44.0, 1e-3);
  EXPECT_NEAR(f.length_after * 1e3, 20.0, 1e-2);
  EXPECT_LT(f.held_out_max_after, 1e-4);
  EXPECT_FALSE(std::isfinite(f.theta1_error));
}

// Two inclinations determine theta2 and L exactly with theta1 held at the material's (the
// inversion of reduced_models.md 3.5): no spare point, so no standard error.
TEST(StopLawFit, TwoInclinationsInvertTheLawExactly) {
  const auto obs = deposits_made_by(42 * kDegree, 15e-3, {29.5, 37}, {});
  const StopLawFit f = fit_stop_law(obs, read_material_text(pine_text()));
  ASSERT_TRUE(f.failure.empty()) << f.failure;
  EXPECT_FALSE(f.theta1_fitted);
  EXPECT_DOUBLE_EQ(in_degrees(f.theta1_after), 27.0);
  EXPECT_EQ(f.law.coefficients.count("theta1"), 0u);
  EXPECT_NEAR(in_degrees(f.theta2_after), 42.0, 1e-4);
  EXPECT_NEAR(f.length_after * 1e3, 15.0, 1e-3);
  EXPECT_LT(f.fit_rms_after, 1e-6);
  EXPECT_FALSE(std::isfinite(f.theta2_error));
}

// Three fitted inclinations free theta1 only when each deposit is known to a quarter of itself: a
// search cut short early (27.6-82.4 mm, the 34 deg search after two layers) counts in the fit but
// leaves theta1 held, so the two precise deposits still set theta2 and L.
TEST(StopLawFit, AWideBracketCountsButDoesNotFreeTheta1) {
  auto obs = deposits_made_by(40 * kDegree, 78e-3, {35, 37}, {});
  obs.push_back({34 * kDegree, 55e-3, 27.4e-3, false});
  const StopLawFit f = fit_stop_law(obs, read_material_text(pine_text()));
  ASSERT_TRUE(f.failure.empty()) << f.failure;
  EXPECT_FALSE(f.theta1_fitted);
  EXPECT_NEAR(in_degrees(f.theta2_after), 40.0, 0.5);
  EXPECT_TRUE(f.band_holds_after[2]);
  obs.back().error_bar = 0.05 * obs.back().reference;  // now precise: theta1 is fitted
  EXPECT_TRUE(fit_stop_law(obs, read_material_text(pine_text())).theta1_fitted);
}

// A deposit thicker at the steeper inclination (the continuum's 63 mm at 29.5 deg and 74 mm at
// 37 deg), one thinning too slowly for any theta2 below 89 deg, and one below theta1: each is
// refused with its reason and the law kept as published.
TEST(StopLawFit, DepositsNoPouliquenLawHoldsAreRefused) {
  const Material pine = read_material_text(pine_text());
  const StopLawFit rising = fit_stop_law(
      {{29.5 * kDegree, 63e-3, 5e-3, false}, {37 * kDegree, 74e-3, 5e-3, false}}, pine);
  EXPECT_NE(rising.failure.find("do not thin"), std::string::npos) << rising.failure;
  EXPECT_DOUBLE_EQ(rising.theta2_after, rising.theta2_before);
  EXPECT_DOUBLE_EQ(rising.length_after, rising.length_before);
  // tan-ratio limit at theta2 -> 90 deg: h(29.5)/h(37) -> 4.34; 2 is slower than any law.
  const StopLawFit slow = fit_stop_law(
      {{29.5 * kDegree, 60e-3, 1e-3, false}, {37 * kDegree, 30e-3, 1e-3, false}}, pine);
  EXPECT_NE(slow.failure.find("89 deg"), std::string::npos) << slow.failure;
  const StopLawFit below =
      fit_stop_law({{25 * kDegree, 90e-3, 1e-3, false}, {37 * kDegree, 30e-3, 1e-3, false}}, pine);
  EXPECT_NE(below.failure.find("at or below theta1"), std::string::npos) << below.failure;
}

// Written beside a drum calibration and read back: theta2 in degrees and L in millimetres in
// the file; the drum's part untouched; a second chute calibration replaces the first.
TEST(ChuteCalibrationToml, RoundTripsBesideTheDrumsCalibration) {
  DrumCalibration drum;
  drum.against = "cel";
  drum.rung = "L2";
  drum.scene = "rotating_drum_20rpm";
  drum.commit = "abc";
  drum.date = "2026-12-06";
  drum.layer.coefficients = {{"layer_fraction", 0.3}, {"friction_shift", 0.0}};
  const std::string with_drum =
      with_calibration(pine_text(), drum_calibration_toml(drum, {}), CalibrationPart::drum);
  const std::vector<ChutePointRecord> points = {{29.5 * kDegree, 48e-3, 4e-3, false, "DEM"}};
  const std::string both = with_calibration(
      with_drum, chute_calibration_toml(chute_example(43.5 * kDegree, 0.0125), points),
      CalibrationPart::chute);
  EXPECT_NE(both.find("theta2 = \"43.5 deg\""), std::string::npos) << both;
  EXPECT_NE(both.find("stop_length = \"12.5 mm\""), std::string::npos) << both;
  const Material m = read_material_text(both);
  ASSERT_TRUE(m.calibration && m.calibration->chute && m.calibration->drum);
  EXPECT_NEAR(m.calibration->chute->law.coefficients.at("theta2"), 43.5 * kDegree, 1e-15);
  EXPECT_NEAR(m.calibration->chute->law.coefficients.at("stop_length"), 0.0125, 1e-15);
  EXPECT_NEAR(m.calibration->chute->highest_angle, 37 * kDegree, 1e-15);
  EXPECT_EQ(m.calibration->chute->points, 1u);
  EXPECT_DOUBLE_EQ(m.calibration->drum->layer.coefficients.at("layer_fraction"), 0.3);
  const Material again = read_material_text(with_calibration(
      both, chute_calibration_toml(chute_example(41 * kDegree, 0.02), {}), CalibrationPart::chute));
  EXPECT_NEAR(again.calibration->chute->law.coefficients.at("theta2"), 41 * kDegree, 1e-15);
  EXPECT_EQ(again.calibration->chute->points, 0u);
  EXPECT_DOUBLE_EQ(again.calibration->drum->layer.coefficients.at("layer_fraction"), 0.3);
  EXPECT_EQ(again.calibration->chute->law.coefficients.count("theta1"), 0u);  // held
  // A fitted theta1 is written in degrees, read back, and the chute check uses it.
  ChuteCalibration fitted = chute_example(41 * kDegree, 0.02);
  fitted.law.coefficients["theta1"] = 25 * kDegree;
  const std::string text = chute_calibration_toml(fitted, {});
  EXPECT_NE(text.find("theta1 = \"25 deg\""), std::string::npos) << text;
  const Material third = read_material_text(with_calibration(both, text, CalibrationPart::chute));
  EXPECT_NEAR(third.calibration->chute->law.coefficients.at("theta1"), 25 * kDegree, 1e-15);
  EXPECT_NEAR(chute_material(third).surface_flow->theta1, 25 * kDegree, 1e-15);
  EXPECT_NEAR(third.surface_flow->theta1, 27 * kDegree, 1e-15);  // the material's kept
}

// theta2 outside (0, 90) deg, L not a length or not above 0, an inverted angle range: refused
// naming the key; a theta2 not above the material's theta1 is refused when the chute check uses it.
TEST(ChuteCalibrationToml, BrokenCoefficientsAreRefusedNamingTheKey) {
  const auto key_of = [](const std::string& table) {
    try {
      const Material m = read_material_text(pine_text() + "\n" + table);
      (void)chute_material(m);
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("accepted");
  };
  const std::string good = chute_calibration_toml(chute_example(43.5 * kDegree, 0.0125), {});
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  EXPECT_EQ(key_of(good), "accepted");
  EXPECT_EQ(key_of(replaced("\"43.5 deg\"", "\"95 deg\"")),
            "calibration.chute.coefficients.theta2");
  EXPECT_EQ(key_of(replaced("\"43.5 deg\"", "\"20 deg\"")),
            "calibration.chute.coefficients.theta2");
  EXPECT_EQ(key_of(replaced("\"12.5 mm\"", "\"12.5 deg\"")),
            "calibration.chute.coefficients.stop_length");
  EXPECT_EQ(key_of(replaced("\"12.5 mm\"", "\"0 mm\"")),
            "calibration.chute.coefficients.stop_length");
  EXPECT_EQ(key_of(replaced("highest_angle = \"37 deg\"", "highest_angle = \"20 deg\"")),
            "calibration.chute.highest_angle");
  // A fitted theta1 not below theta2.
  EXPECT_EQ(key_of(replaced("theta2 = ", "theta1 = \"50 deg\", theta2 = ")),
            "calibration.chute.coefficients.theta1");
  EXPECT_EQ(key_of(replaced("theta2 = ", "theta1 = \"20 deg\", theta2 = ")), "accepted");
}

// The seed plane at 29.5 deg: the calibrated law gives its h_stop (45 deg, 25 mm), the model
// text and the assumptions name the calibration, the band holds +-8 % (its largest error), and
// a chute at 40 deg, beyond the calibrated 29.5-37 deg, says it is extrapolated.
TEST(ChuteCalibration, DesignUsesTheCalibrationAndSaysSo) {
  Case c = load_case("cases/inclined_plane_29_5.toml");
  c.material = read_material_text(pine_text());
  const DesignRecord before = design_check(c);
  c.material = read_material_text(
      with_calibration(pine_text(), chute_calibration_toml(chute_example(45 * kDegree, 0.025), {}),
                       CalibrationPart::chute));
  const DesignRecord after = design_check(c);
  const Estimate& h0 = *find_estimate(before.results, "stopping_thickness");
  const Estimate& h1 = *find_estimate(after.results, "stopping_thickness");
  const double expected = h_stop(45 * kDegree, 0.025, 29.5 * kDegree);
  EXPECT_NEAR(std::get<double>(h1.value), expected, 1e-12);
  EXPECT_GT(std::get<double>(h1.value), 2 * std::get<double>(h0.value));
  EXPECT_NE(h1.model.find("calibrated against L3 DEM"), std::string::npos) << h1.model;
  EXPECT_LE(*h1.low, 0.92 * expected + 1e-12);
  EXPECT_GE(*h1.high, 1.08 * expected - 1e-12);
  const auto said = [](const DesignRecord& r, const char* what) {
    for (const auto& a : r.assumptions)
      if (a.find(what) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(said(after, "[calibration.chute]"));
  EXPECT_FALSE(said(after, "extrapolated"));
  EXPECT_TRUE(said(before, "assumed calibration targets"));
  std::get<Chute>(c.equipment).angle = 40 * kDegree;
  EXPECT_TRUE(said(design_check(c), "extrapolated"));
}

// A design point is a bench deposit question at its inclination on the design's case: the CEL
// refinement series down to the finest cell (no variants), all in the reference until their
// runs show what they resolve; or the DEM reference alone: h_stop verified by the bisection of
// stopping layers (the seed's whole plane is 100 h an angle).
TEST(ChuteCalibrationDesign, EachPointIsABenchDepositQuestion) {
  ChuteCalibrationDesign d;
  d.case_file = "cases/inclined_plane_29_5.toml";
  d.points = inclination_points({29.5 * kDegree, 33 * kDegree}, {31 * kDegree});
  d.finest_cell = 10e-3;
  d.check();
  const BenchQuestion q = chute_point_question(d, d.points[1]);
  EXPECT_EQ(q.id, "chute_deposit_33deg");
  EXPECT_EQ(q.sets, std::vector<std::string>{"chute.angle=33deg"});
  ASSERT_EQ(q.points.size(), 2u);
  for (const auto& p : q.points) {
    EXPECT_EQ(p.role, ReferenceRole::cel_refinement);
    EXPECT_EQ(p.rest_key, "at_rest");
  }
  d.against = "dem";
  const BenchQuestion dem = chute_point_question(d, d.points[0]);
  ASSERT_EQ(dem.points.size(), 1u);
  EXPECT_EQ(dem.points[0].role, ReferenceRole::dem_reference);
  EXPECT_EQ(dem.points[0].verify, "dem");
  EXPECT_EQ(dem.points[0].quantity, "stopping_thickness");
  EXPECT_EQ(bench_invocation(dem, dem.points[0]),
            "design cases/inclined_plane_29_5.toml --set chute.angle=29.5deg --verify dem "
            "--budget 10000h");
  // One fitted inclination, or one given twice, is refused by flag.
  d.points = inclination_points({29.5 * kDegree}, {31 * kDegree});
  EXPECT_THROW(d.check(), InputError);
  d.points = inclination_points({29.5 * kDegree, 33 * kDegree}, {33 * kDegree});
  EXPECT_THROW(d.check(), InputError);
}

// Runs of 20, 10 and 5 mm at rest with deposits of 45, 50 and 52 mm: the 20 mm level has 2.25
// cells across its own deposit and leaves the reference; two levels are left. With the 10 mm
// level at 25 mm (2.5 cells), or the 5 mm level still flowing, one is left, and the point says
// why it has no reference.
TEST(ChuteCalibrationDesign, ALevelThatCannotResolveItsDepositLeavesTheReference) {
  ChuteCalibrationDesign d;
  d.case_file = "cases/inclined_plane_29_5.toml";
  d.points = inclination_points({29.5 * kDegree, 33 * kDegree}, {});
  d.finest_cell = 5e-3;
  // The runs' deposits by cell size; the level `flowing_cell` ended still flowing.
  const auto runs_with = [&](const BenchQuestion& q, std::map<double, double> deposit_mm,
                             double flowing_cell = 0.0) {
    std::map<std::string, BenchRun> runs;
    for (const auto& p : q.points) {
      BenchRun r;
      r.results = {
          {"deposit_thickness_mid_ramp",
           {{"value", deposit_mm.at(*p.cell_size) * 1e-3}, {"unit", "m"}}},
          {"at_rest", {{"value", *p.cell_size == flowing_cell ? "no (time limit)" : "yes"}}}};
      runs[point_id(p)] = r;
    }
    return runs;
  };
  BenchQuestion q = chute_point_question(d, d.points[0]);
  ASSERT_EQ(q.points.size(), 3u);
  EXPECT_EQ(keep_resolving_levels(q, runs_with(q, {{0.02, 45}, {0.01, 50}, {0.005, 52}})), "");
  for (const auto& p : q.points)
    EXPECT_EQ(p.role, *p.cell_size > 0.015 ? ReferenceRole::none : ReferenceRole::cel_refinement);
  BenchQuestion thin = chute_point_question(d, d.points[0]);
  const std::string why =
      keep_resolving_levels(thin, runs_with(thin, {{0.02, 45}, {0.01, 25}, {0.005, 26}}));
  EXPECT_NE(why.find("on 1 CEL level(s) at rest"), std::string::npos) << why;
  EXPECT_NE(why.find("finer --finest-cell"), std::string::npos) << why;
  // A resolving level still flowing at the end (an upper bound) does not count either.
  BenchQuestion flowing = chute_point_question(d, d.points[0]);
  const std::string late = keep_resolving_levels(
      flowing, runs_with(flowing, {{0.02, 45}, {0.01, 50}, {0.005, 52}}, 0.005));
  EXPECT_NE(late.find("1 still flowing"), std::string::npos) << late;
}

}  // namespace
}  // namespace feedflow
