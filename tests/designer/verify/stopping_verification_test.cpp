// A chute's h_stop verified on the particle rung (designer/verify/stopping_verification): the
// band the layers search, the bracket kept layers give without a DEM step, and what the record
// says of it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "designer/calibrate/stopping_records.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/design/design_check.hpp"
#include "designer/verify/design_verification.hpp"
#include "designer/verify/stopping_verification.hpp"
#include "kept_runs.hpp"
#include "models/core/errors.hpp"
#include "reports/result_format.hpp"
#include "reports/results_json.hpp"

namespace feedflow {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path d =
      fs::temp_directory_path() / ("feedflow_stopping_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  return d;
}

// The seed's 37 deg plane: the layers start in the reduced h_stop band (the shipped pine's
// calibrated law: 25.9 mm, band 14.4-42 mm), one of the seed's spheres (3 mm) is the default
// tolerance and the floor, 40 of them the ceiling; the plan's runs are those of a bisection of
// its band. At 29.5 deg the band's top (444 mm) is cut to the ceiling.
TEST(StoppingVerification, TheLayersSearchTheReducedBandToOneSphere) {
  const Case c = load_case("cases/inclined_plane_37.toml", std::vector<SetOverride>{});
  const DesignRecord record = design_check(c, ModelChoices{});
  const Estimate* reduced = find_estimate(record.results, "stopping_thickness");
  ASSERT_TRUE(reduced && reduced->low && reduced->high);
  const auto plan = plan_stopping_verification(c, record, 0.0);
  const double per = reduced->unit == "mm" ? 1e-3 : 1.0;
  EXPECT_DOUBLE_EQ(plan.tolerance, 0.003);
  EXPECT_DOUBLE_EQ(plan.floor, 0.003);
  EXPECT_DOUBLE_EQ(plan.ceiling, 0.120);
  EXPECT_NEAR(plan.low, *reduced->low * per, 1e-12);
  EXPECT_NEAR(plan.high, *reduced->high * per, 1e-12);
  EXPECT_EQ(plan.runs, bisection_runs(plan.low, plan.high, 0.003));
  EXPECT_GT(plan.seconds, 0.0);
  EXPECT_THROW(plan_stopping_verification(c, record, -1.0), InputError);
  const Case low = load_case("cases/inclined_plane_29_5.toml", std::vector<SetOverride>{});
  EXPECT_DOUBLE_EQ(plan_stopping_verification(low, design_check(low, ModelChoices{}), 0.0).high,
                   0.120);
  // Near theta1 the whole band lies above the ceiling (28 deg: h_stop 521 mm): the layers search
  // just below it; a tolerance above a quarter of the layers' range is refused.
  const Case flat = load_case("cases/inclined_plane_29_5.toml",
                              std::vector<SetOverride>{{"chute.angle", "28deg"}});
  const auto top = plan_stopping_verification(flat, design_check(flat, ModelChoices{}), 0.0);
  EXPECT_DOUBLE_EQ(top.high, 0.120);
  EXPECT_DOUBLE_EQ(top.low, 0.114);
  EXPECT_THROW(plan_stopping_verification(c, record, 0.05), InputError);
  // Above the law's theta2 (45.5 deg) the reduced rung leaves no layer: the layers search one
  // to ten spheres.
  const Case steep = load_case("cases/inclined_plane_29_5.toml",
                               std::vector<SetOverride>{{"chute.angle", "47deg"}});
  const auto none = plan_stopping_verification(steep, design_check(steep, ModelChoices{}), 0.0);
  EXPECT_FALSE(none.reduced_low);
  EXPECT_DOUBLE_EQ(none.low, 0.003);
  EXPECT_DOUBLE_EQ(none.high, 0.030);
}

// Layers kept from an earlier call are read back (no DEM step): laid down as a layer thinner
// than 9 mm rests and a thicker one flows, the twin's bracket at 37 deg holds 9 mm within one
// sphere (6 mm) after the band's bottom (14.4 mm) flowed and was halved; it lies below the
// reduced band (14.4-42 mm), so it is contradicted; the DEM bracket takes the stopping
// thickness's place (L3, in metres), the reduced one is kept beside it, and the note gives the
// layers and the thickness measured at rest.
TEST(StoppingVerification, KeptLayersBracketHStopWithoutADemStep) {
  const std::string file = "tests/data/dem_layer_twin.toml";
  const Case c = load_case(file, std::vector<SetOverride>{});
  DesignRecord record = design_check(c, ModelChoices{});
  const auto plan = plan_stopping_verification(c, record, 0.0);
  const fs::path runs = scratch("kept");
  // Lays each layer down as the bisection asks for it.
  const auto laid = bisect_flow_threshold(
      plan.low, plan.high, plan.tolerance,
      [&](double h) -> std::optional<bool> {
        const bool flows = h >= 0.009;
        testing::lay_down_layer(file, {}, runs, h, flows ? "flowing" : "at rest", 0.9 * h, 30.0);
        return flows;
      },
      plan.floor, plan.ceiling, kLayerGrid);
  const StoppingVerification v = verify_stopping(file, {}, plan, 0.0, runs, nullptr);
  EXPECT_EQ(v.status, "done");
  EXPECT_EQ(v.wall_seconds, 0.0);  // all read back
  ASSERT_EQ(v.bisection.end, ThresholdBisection::End::bracketed);
  EXPECT_EQ(v.bisection.steps.size(), laid.steps.size());  // replayed as it was made
  EXPECT_EQ(v.bisection.stops_at, laid.stops_at);
  EXPECT_EQ(v.bisection.flows_at, laid.flows_at);
  EXPECT_LT(v.bisection.stops_at, 0.009);
  EXPECT_GE(v.bisection.flows_at, 0.009);
  EXPECT_LT(v.bisection.stops_at, *plan.reduced_low);  // widened below the band
  EXPECT_LE(v.bisection.flows_at - v.bisection.stops_at, 0.006 + 1e-12);
  ASSERT_TRUE(v.rested_thickness);
  EXPECT_DOUBLE_EQ(*v.rested_thickness, 0.9 * v.bisection.stops_at);
  apply_stopping_verification(c, plan, v, record);
  const Estimate* h = find_estimate(record.results, "stopping_thickness");
  ASSERT_NE(h, nullptr);
  EXPECT_EQ(h->rung, Rung::L3);
  EXPECT_EQ(h->unit, "m");
  EXPECT_DOUBLE_EQ(*h->low, v.bisection.stops_at);
  EXPECT_DOUBLE_EQ(*h->high, v.bisection.flows_at);
  EXPECT_NE(find_estimate(record.results, reduced_model_key("stopping_thickness")), nullptr);
  const std::string& note = record.verdict.reasons.back();
  EXPECT_NE(note.find("stopping thickness contradicted on the particle rung"), std::string::npos)
      << note;
  EXPECT_NE(note.find("measured at rest"), std::string::npos) << note;
  fs::remove_all(runs);
}

// Layers kept from a search that started elsewhere (a plan of an earlier material, say) still
// count: a layer resting above the plan's band and a thicker one flowing, within a tolerance,
// bracket h_stop without a DEM step, as a third that contradicts them (resting thicker than one
// that flows) and a layer at another angle are passed over.
TEST(StoppingVerification, LayersOfAnotherSearchNarrowTheBand) {
  const std::string file = "tests/data/dem_layer_twin.toml";
  const Case c = load_case(file, std::vector<SetOverride>{});
  const DesignRecord record = design_check(c, ModelChoices{});
  const auto plan = plan_stopping_verification(c, record, 0.0);
  const fs::path runs = scratch("elsewhere");
  const double rests = plan.high + 2.0 * plan.tolerance, flows = rests + 0.9 * plan.tolerance;
  testing::lay_down_layer(file, {}, runs, rests, "at rest", rests, 30.0);
  testing::lay_down_layer(file, {}, runs, flows, "flowing", flows, 30.0);
  testing::lay_down_layer(file, {}, runs, flows + plan.tolerance, "at rest", flows, 30.0);
  testing::lay_down_layer(file, {"chute.angle=30deg"}, runs, plan.low, "flowing", plan.low, 30.0);
  std::ostringstream progress;
  const StoppingVerification v = verify_stopping(file, {}, plan, 0.0, runs, &progress);
  EXPECT_EQ(v.status, "done") << progress.str();
  EXPECT_EQ(v.wall_seconds, 0.0);
  ASSERT_EQ(v.bisection.end, ThresholdBisection::End::bracketed) << progress.str();
  EXPECT_NEAR(v.bisection.stops_at, rests, 1e-9);
  EXPECT_NEAR(v.bisection.flows_at, flows, 1e-9);
  EXPECT_NE(progress.str().find("narrow it to"), std::string::npos) << progress.str();
  fs::remove_all(runs);
}

// Without kept layers, a budget below the plan's estimate starts none: `design --verify dem`
// says what the bisection would take and the command whose budget holds it.
TEST(StoppingVerification, ABudgetBelowTheEstimateStartsNoLayer) {
  const std::string file = "tests/data/dem_layer_twin.toml";
  const Case c = load_case(file, std::vector<SetOverride>{});
  DesignRecord record = design_check(c, ModelChoices{});
  VerificationRequest request;
  request.case_file = file;
  request.mode = "dem";
  request.budget = "1 s";
  request.runs = scratch("budget");
  ASSERT_TRUE(verify_design(request, c, record));
  const std::string& note = record.verdict.reasons.back();
  EXPECT_NE(note.find("beyond the budget of 1 s"), std::string::npos) << note;
  EXPECT_NE(note.find("--verify dem --budget"), std::string::npos) << note;
  EXPECT_FALSE(fs::exists(request.runs / "verify_stopping"));
  EXPECT_EQ(find_estimate(record.results, "stopping_thickness")->rung, Rung::L0);
  fs::remove_all(request.runs);
}

// An earlier record's bracket (a search made on another machine, its runs gone) answers for its
// two layers without a run: with only the layers inside it kept here, a budget of nothing still
// brackets h_stop inside it, a record's layer named as such; without it, a run is wanted.
TEST(StoppingVerification, AnEarlierRecordsLayersAreNotMadeAgain) {
  const std::string file = "tests/data/dem_layer_twin.toml";
  const Case c = load_case(file, std::vector<SetOverride>{});
  const DesignRecord record = design_check(c, ModelChoices{});
  const auto plan = plan_stopping_verification(c, record, 0.0);
  const fs::path runs = scratch("earlier");
  const double rests = 0.0105, flows = rests + 3.5 * plan.tolerance, threshold = rests + 0.02;
  // The layers a bisection of the record's bracket asks inside it, laid down here.
  const auto inside = bisect_flow_threshold(
      rests, flows, plan.tolerance,
      [&](double h) -> std::optional<bool> {
        if (h == rests || h == flows) return h == flows;  // the record's, not laid down
        testing::lay_down_layer(file, {}, runs, h, h >= threshold ? "flowing" : "at rest", h, 30.0);
        return h >= threshold;
      },
      0.0, 0.0, kLayerGrid);
  ASSERT_EQ(inside.end, ThresholdBisection::End::bracketed);
  ASSERT_GE(inside.steps.size(), 4u);  // two of the record's, at least two made inside
  std::ostringstream progress;
  const EarlierLayers earlier{{rests, false}, {flows, true}};
  const StoppingVerification v = verify_stopping(file, {}, plan, 0.0, runs, &progress, earlier);
  EXPECT_EQ(v.status, "done") << progress.str();
  EXPECT_EQ(v.wall_seconds, 0.0);
  ASSERT_EQ(v.bisection.end, ThresholdBisection::End::bracketed) << progress.str();
  EXPECT_EQ(v.bisection.stops_at, inside.stops_at);
  EXPECT_EQ(v.bisection.flows_at, inside.flows_at);
  EXPECT_LE(v.bisection.flows_at - v.bisection.stops_at, plan.tolerance);
  std::size_t named = 0;
  for (auto at = progress.str().find("(earlier record)"); at != std::string::npos;
       at = progress.str().find("(earlier record)", at + 1))
    ++named;
  EXPECT_GE(named, 1u) << progress.str();
  const StoppingVerification alone = verify_stopping(file, {}, plan, 0.0, runs, nullptr);
  EXPECT_NE(alone.status, "done");  // the record's layers were what answered
  fs::remove_all(runs);
}

// A search cut short (its budget below the layers still to make) keeps its bracket so far beside
// the reduced answer, unjudged; its record read back gives that bracket, and a search started
// from it on a machine without the runs begins there (the record keeps a thickness to 1 nm), while
// one at another angle is refused naming the record's key.
TEST(StoppingVerification, ASearchCutShortLeavesABracketToStartFrom) {
  const std::string file = "tests/data/dem_layer_twin.toml";
  const Case c = load_case(file, std::vector<SetOverride>{});
  DesignRecord record = design_check(c, ModelChoices{});
  const auto plan = plan_stopping_verification(c, record, 0.0);
  VerificationRequest request;
  request.case_file = file;
  request.mode = "dem";
  request.budget = "1 s";
  request.runs = scratch("cut_short");
  const double rests = plan.high + plan.tolerance, flows = rests + 4.0 * plan.tolerance;
  testing::lay_down_layer(file, {}, request.runs, rests, "at rest", rests, 30.0);
  testing::lay_down_layer(file, {}, request.runs, flows, "flowing", flows, 30.0);
  ASSERT_TRUE(verify_design(request, c, record));
  EXPECT_EQ(find_estimate(record.results, "stopping_thickness")->rung, Rung::L0);  // not judged
  const Estimate* so_far = find_estimate(record.results, "stopping_thickness_so_far");
  ASSERT_NE(so_far, nullptr) << record.verdict.reasons.back();
  EXPECT_EQ(so_far->rung, Rung::L3);
  EXPECT_NEAR(*so_far->low, rests, 1e-9);
  EXPECT_NEAR(*so_far->high, flows, 1e-9);
  EXPECT_NE(record.verdict.reasons.back().find("layers so far"), std::string::npos);
  const fs::path saved = request.runs / "results.json";
  std::ofstream(saved) << to_json(record).dump(2);
  const StoppingRecord read = read_stopping_record(saved, c.material.name, "--start-from");
  EXPECT_TRUE(read.so_far);
  EXPECT_EQ(read.law, "hertz");
  EXPECT_NEAR(read.stops_at, rests, 1e-9);
  EXPECT_NEAR(read.flows_at, flows, 1e-9);

  DesignRecord again = design_check(c, ModelChoices{});
  VerificationRequest elsewhere = request;
  elsewhere.runs = scratch("cut_short_elsewhere");
  elsewhere.start_from = saved;
  ASSERT_TRUE(verify_design(elsewhere, c, again));
  const Estimate* resumed = find_estimate(again.results, "stopping_thickness_so_far");
  ASSERT_NE(resumed, nullptr) << again.verdict.reasons.back();
  EXPECT_NEAR(*resumed->low, rests, 1e-9);
  EXPECT_NEAR(*resumed->high, flows, 1e-9);
  EXPECT_NE(again.verdict.reasons.back().find("--start-from"), std::string::npos)
      << again.verdict.reasons.back();

  const Case steeper =
      load_case(file, std::vector<SetOverride>{parse_set_override("chute.angle=40deg")});
  DesignRecord other = design_check(steeper, ModelChoices{});
  try {
    verify_design(elsewhere, steeper, other);
    ADD_FAILURE() << "a record of 37 deg started a search at 40 deg";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "inputs.chute.angle") << e.what();
  }
  fs::remove_all(request.runs);
  fs::remove_all(elsewhere.runs);
}

}  // namespace
}  // namespace feedflow
