// The bench harness (designer/bench): its plan, its references, errors and Pareto front on
// synthetic runs, and its saved runs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "designer/bench/bench_plan.hpp"
#include "designer/bench/bench_run.hpp"
#include "designer/bench/bench_table.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/case/material_text.hpp"
#include "fullsim/common/scene_run.hpp"
#include "models/numerics/richardson.hpp"
#include "models/os/interrupt_request.hpp"

namespace feedflow {
namespace {

// A run that answered `quantity` with a number and band, in `seconds`.
BenchRun number_run(const std::string& quantity, double value, double low, double high,
                    double seconds) {
  BenchRun r;
  r.invocation = "synthetic";
  r.wall_seconds = seconds;
  r.results[quantity] = {{"value", value}, {"unit", "kg/s"}, {"low", low}, {"high", high}};
  return r;
}

BenchRun label_run(const std::string& quantity, const std::string& label, double seconds) {
  BenchRun r;
  r.invocation = "synthetic";
  r.wall_seconds = seconds;
  r.results[quantity] = {{"value", label}, {"unit", ""}};
  return r;
}

BenchPoint point(const std::string& setting, const std::string& rung,
                 ReferenceRole role = ReferenceRole::none,
                 std::optional<double> cell = std::nullopt) {
  BenchPoint p;
  p.setting = setting;
  p.rung = rung;
  p.quantity = "mass_flow_rate";
  p.role = role;
  p.cell_size = cell;
  return p;
}

// Every point of the plan is a case the loader accepts (its case file, the question's and the
// point's settings), its id is unique within its question, and every question has reference
// runs: the DEM run with the seed's law, and CEL levels that resolve its feature (3 cells
// across): three for a number (Richardson), one for a label, none for the 37 deg deposit
// (3.5 mm: no level of 1 mm or more resolves it) and none for B_c (the continuum cannot arch:
// its reference is the DEM's bisection, a verified design check).
TEST(BenchPlan, EveryPointIsAValidCaseWithReferenceRuns) {
  const auto questions = seed_bench_questions();
  EXPECT_GE(questions.size(), 12u);  // hopper x4, chute x2, drum x6
  for (const auto& q : questions) {
    std::set<std::string> ids;
    int levels = 0, dem = 0, quick = 0;
    for (const auto& p : q.points) {
      EXPECT_TRUE(ids.insert(point_id(p)).second) << q.id << ": " << p.setting;
      std::vector<SetOverride> overrides;
      for (const auto& s : q.sets) overrides.push_back(parse_set_override(s));
      for (const auto& s : p.sets) overrides.push_back(parse_set_override(s));
      EXPECT_NO_THROW(
          load_case((std::filesystem::path(FEEDFLOW_SOURCE_DIR) / q.case_file).string(), overrides))
          << bench_invocation(q, p);
      levels += p.role == ReferenceRole::cel_refinement;
      dem += p.role == ReferenceRole::dem_reference;
      quick += p.quick;
    }
    if (q.id == "chute_stopping_thickness_37" || q.id == "hopper_critical_outlet_width")
      EXPECT_EQ(levels, 0);
    else
      EXPECT_GE(levels, q.categorical ? 1 : 3) << q.id;
    EXPECT_EQ(dem, 1) << q.id;
    EXPECT_GE(quick, 2) << q.id;  // a reduced-model point and a coarse CEL point at least
  }
}

// The reference of a number is the Richardson limit of the CEL series (values on a first-order
// power law: the limit itself); each answer's error is relative to it, a band that holds it
// says so, the Pareto front is what no point beats on both time and error, and a DEM reference
// far outside both error bars is reported as a disagreement.
TEST(BenchTable, RichardsonReferenceErrorsBandsAndFront) {
  BenchQuestion q{"rate", "rate", "cases/pilot_hopper.toml", {}, false, {}, {}, {}};
  q.points = {point("beverloo", "L0"),
              point("johanson", "L0"),
              point("CEL 20", "L2", ReferenceRole::cel_refinement, 0.02),
              point("CEL 10", "L2", ReferenceRole::cel_refinement, 0.01),
              point("CEL 5", "L2", ReferenceRole::cel_refinement, 0.005),
              point("DEM seed law", "L3", ReferenceRole::dem_reference)};
  std::map<std::string, BenchRun> runs;
  auto cel = [](double h) { return 5.0 + 40.0 * h; };                                // limit 5 kg/s
  runs[point_id(q.points[0])] = number_run("mass_flow_rate", 4.5, 4.0, 5.5, 0.003);  // band holds 5
  runs[point_id(q.points[1])] =
      number_run("mass_flow_rate", 6.0, 5.5, 6.5, 0.004);  // slower, worse
  runs[point_id(q.points[2])] = number_run("mass_flow_rate", cel(0.02), 5.7, 5.9, 2.0);
  runs[point_id(q.points[3])] = number_run("mass_flow_rate", cel(0.01), 5.3, 5.5, 11.0);
  runs[point_id(q.points[4])] = number_run("mass_flow_rate", cel(0.005), 5.1, 5.3, 170.0);
  runs[point_id(q.points[5])] = number_run("mass_flow_rate", 7.0, 6.8, 7.2, 900.0);
  const BenchQuestionTable t = tabulate(q, runs);
  ASSERT_TRUE(t.reference.value);
  EXPECT_NEAR(*t.reference.value, 5.0, 1e-9);
  EXPECT_NE(t.reference.source.find("Richardson"), std::string::npos);
  EXPECT_NE(t.reference.agreement.find("disagree"), std::string::npos);
  EXPECT_NEAR(*t.answers[0].error, 0.1, 1e-12);
  EXPECT_TRUE(*t.answers[0].band_holds_reference);
  EXPECT_FALSE(*t.answers[1].band_holds_reference);
  EXPECT_NEAR(*t.answers[4].error, 0.2 / 5.0, 1e-12);
  const std::vector<bool> front{t.answers[0].pareto, t.answers[1].pareto, t.answers[2].pareto,
                                t.answers[3].pareto, t.answers[4].pareto, t.answers[5].pareto};
  // beverloo (fastest), CEL 10 mm (cheaper than CEL 5, closer than beverloo), CEL 5 mm (closest)
  EXPECT_EQ(front, (std::vector<bool>{true, false, false, true, true, false}));
  const auto chart = error_against_time_chart(t);
  ASSERT_TRUE(chart);
  EXPECT_TRUE(chart->x.logarithmic && chart->y.logarithmic);
  EXPECT_EQ(chart->series.back().label, "Pareto front");
  EXPECT_EQ(chart->series.back().x, (std::vector<double>{0.003, 11.0, 170.0}));
}

// A deposit's run that ended still flowing answers an upper bound: it stays out of the
// reference (two settled levels extrapolate to the limit 5 of 5 + 40 h), off the Pareto front
// (though the closest), and its JSON and CSV rows say so.
TEST(BenchTable, ARunNotAtRestIsAnUpperBoundOutOfTheReference) {
  BenchQuestion q{"deposit", "deposit", "cases/inclined_plane_29_5.toml", {}, false, {}, {}, {}};
  q.points = {point("CEL 20", "L2", ReferenceRole::cel_refinement, 0.02),
              point("CEL 10", "L2", ReferenceRole::cel_refinement, 0.01),
              point("CEL 5", "L2", ReferenceRole::cel_refinement, 0.005)};
  for (auto& p : q.points) p.rest_key = "at_rest";
  std::map<std::string, BenchRun> runs;
  const auto run = [](double value, double seconds, const char* rest) {
    BenchRun r = number_run("mass_flow_rate", value, value - 0.1, value + 0.1, seconds);
    r.results["at_rest"] = {{"value", rest}, {"unit", ""}};
    return r;
  };
  runs[point_id(q.points[0])] = run(5.8, 2.0, "yes");
  runs[point_id(q.points[1])] = run(5.4, 11.0, "yes");
  runs[point_id(q.points[2])] = run(5.05, 170.0, "no (time limit)");
  const BenchQuestionTable t = tabulate(q, runs);
  ASSERT_TRUE(t.reference.value);
  EXPECT_NEAR(*t.reference.value, 5.0, 1e-9);
  EXPECT_NE(t.reference.source.find("two levels (20, 10 mm"), std::string::npos)
      << t.reference.source;
  EXPECT_EQ(t.answers[1].at_rest, std::optional<bool>(true));
  EXPECT_EQ(t.answers[2].at_rest, std::optional<bool>(false));
  EXPECT_TRUE(t.answers[2].error);    // its error is shown ...
  EXPECT_FALSE(t.answers[2].pareto);  // ... but it is not ranked
  EXPECT_TRUE(t.answers[1].pareto);
  const auto json = bench_json({t});
  EXPECT_EQ(json[0]["answers"][2]["at_rest"], false);
  EXPECT_NE(bench_csv({t}).find("done (not at rest: an upper bound)"), std::string::npos);
}

// A verified point whose verification did not answer on its rung (a search cut short) leaves the
// reduced answer in the results: the point has no answer and no reference, rather than taking the
// reduced model's value as the DEM's.
TEST(BenchTable, AVerificationThatLeftTheReducedAnswerIsNoAnswer) {
  BenchQuestion q{"h_stop", "h_stop", "cases/inclined_plane_37.toml", {}, false, {}, {}, {}};
  BenchPoint layers = point("DEM stopping layers", "L3", ReferenceRole::dem_reference);
  layers.quantity = "stopping_thickness";
  layers.verify = "dem";
  q.points = {layers};
  std::map<std::string, BenchRun> runs;
  BenchRun r = number_run("stopping_thickness", 0.0259, 0.0144, 0.042, 30.0);
  r.results["stopping_thickness"]["rung"] = "L0";
  runs[point_id(layers)] = r;
  const BenchQuestionTable left = tabulate(q, runs);
  EXPECT_FALSE(left.answers[0].value);
  EXPECT_NE(left.answers[0].label.find("not answered on L3"), std::string::npos)
      << left.answers[0].label;
  EXPECT_FALSE(left.reference.value);
  runs[point_id(layers)].results["stopping_thickness"]["rung"] = "L3";
  const BenchQuestionTable answered = tabulate(q, runs);
  ASSERT_TRUE(answered.reference.value);
  EXPECT_DOUBLE_EQ(*answered.reference.value, 0.0259);
}

// Levels that do not converge monotonically (the drum at 20 rpm: 36.7, 38.3, 45.7 deg on 20, 10,
// 5 mm) give no order: the finest run is the reference, with the spread as its error bar, and
// has no error of its own (it is not a point on the front).
TEST(BenchTable, DivergingLevelsGiveTheFinestRunWithTheSpread) {
  BenchQuestion q{"angle", "angle", "cases/rotating_drum_20rpm.toml", {}, false, {}, {}, {}};
  q.points = {point("design", "L0"), point("CEL 20", "L2", ReferenceRole::cel_refinement, 0.02),
              point("CEL 10", "L2", ReferenceRole::cel_refinement, 0.01),
              point("CEL 5", "L2", ReferenceRole::cel_refinement, 0.005)};
  std::map<std::string, BenchRun> runs;
  const double angles[] = {39.1, 36.7, 38.3, 45.7};
  for (int k = 0; k < 4; ++k)
    runs[point_id(q.points[k])] =
        number_run("mass_flow_rate", angles[k], angles[k], angles[k], k + 1.0);
  const BenchQuestionTable t = tabulate(q, runs);
  EXPECT_NE(t.reference.source.find("no observed order"), std::string::npos);
  EXPECT_DOUBLE_EQ(*t.reference.value, 45.7);
  EXPECT_NEAR(*t.reference.error_bar, 9.0, 1e-9);
  EXPECT_FALSE(t.answers[3].error);
  EXPECT_FALSE(t.answers[3].pareto);
  EXPECT_NEAR(*t.answers[0].error, (45.7 - 39.1) / 45.7, 1e-12);
}

// A time average's statistical interval enters the references: the drum's angle on a first-order
// series 40 + 200 h has Richardson's bar widened by the finest level's 95 % interval in
// quadrature; the DEM reference's error bar is its interval (0.8 deg), not half its 2 SD band
// (10 deg), so a 3.5 deg gap is a disagreement; the hopper's rate, whose band is its interval,
// takes the band's half-width.
TEST(BenchTable, TheFinestLevelsIntervalWidensTheReference) {
  BenchQuestion q{"angle", "angle", "cases/rotating_drum_20rpm.toml", {}, false, {}, {}, {}};
  q.points = {point("CEL 20", "L2", ReferenceRole::cel_refinement, 0.02),
              point("CEL 10", "L2", ReferenceRole::cel_refinement, 0.01),
              point("CEL 5", "L2", ReferenceRole::cel_refinement, 0.005),
              point("DEM seed law", "L3", ReferenceRole::dem_reference)};
  for (auto& p : q.points) {
    p.quantity = "dynamic_angle_of_repose";
    p.interval_key = "dynamic_angle_of_repose_interval";
  }
  std::map<std::string, BenchRun> runs;
  const auto run = [](double angle, double interval) {
    BenchRun r = number_run("dynamic_angle_of_repose", angle, angle - 10.0, angle + 10.0, 1.0);
    r.results["dynamic_angle_of_repose"]["unit"] = "deg";
    r.results["dynamic_angle_of_repose_interval"] = {{"value", interval}, {"unit", "deg"}};
    return r;
  };
  runs[point_id(q.points[0])] = run(44.0, 3.0);
  runs[point_id(q.points[1])] = run(42.0, 2.0);
  runs[point_id(q.points[2])] = run(41.0, 1.5);
  runs[point_id(q.points[3])] = run(43.5, 0.8);
  const BenchQuestionTable t = tabulate(q, runs);
  ASSERT_TRUE(t.reference.value && t.reference.error_bar && t.reference.order);
  EXPECT_NEAR(*t.reference.value, 40.0, 1e-9);
  const RichardsonEstimate grid = richardson({0.02, 0.01, 0.005}, {44.0, 42.0, 41.0});
  EXPECT_NEAR(*t.reference.error_bar, std::hypot(grid.error_bar, 1.5), 1e-12);
  EXPECT_NE(t.reference.source.find("95 % interval +-1.5 deg in quadrature"), std::string::npos)
      << t.reference.source;
  EXPECT_DOUBLE_EQ(*t.answers[2].interval, 1.5);
  EXPECT_LT(*t.reference.error_bar + 0.8, 3.5);   // so DEM 43.5 disagrees ...
  EXPECT_GT(*t.reference.error_bar + 10.0, 3.5);  // ... where half its band would have agreed
  EXPECT_NE(t.reference.agreement.find("CEL and DEM disagree"), std::string::npos)
      << t.reference.agreement;
  EXPECT_NE(t.reference.agreement.find("DEM 43.5 +- 0.8 deg"), std::string::npos)
      << t.reference.agreement;
  EXPECT_NEAR(bench_json({t})[0]["answers"][3]["interval"].get<double>(), 0.8, 1e-12);
  // the chart draws the reference's error bar in % across the points' wall times
  const auto chart = error_against_time_chart(t);
  ASSERT_TRUE(chart);
  const auto bar =
      std::find_if(chart->series.begin(), chart->series.end(), [](const ChartSeries& s) {
        return s.label.find("error bar") != std::string::npos;
      });
  ASSERT_NE(bar, chart->series.end());
  EXPECT_NEAR(bar->y.at(0), 100.0 * *t.reference.error_bar / 40.0, 1e-9);

  // the rate: its band is its interval
  BenchPoint rate = point("CEL 5", "L2", ReferenceRole::cel_refinement, 0.005);
  rate.interval_key = rate.quantity;
  BenchQuestion r{"rate", "rate", "cases/pilot_hopper.toml", {}, false, {rate}, {}, {}};
  const BenchQuestionTable tr =
      tabulate(r, {{point_id(rate), number_run("mass_flow_rate", 5.4, 5.3, 5.6, 1.0)}});
  EXPECT_NEAR(*tr.answers[0].interval, 0.15, 1e-12);
}

// Labels are right (0) or wrong (1) against the finest CEL level; a point not run, one that
// failed and one without the quantity have no error and are not on the front.
TEST(BenchTable, LabelsAreRightOrWrongAgainstTheFinestLevel) {
  BenchQuestion q{"arch", "arch", "cases/pilot_hopper.toml", {}, true, {}, {}, {}};
  q.points = {point("jenike", "L0"),
              point("static arch", "L0"),
              point("CEL 20", "L2", ReferenceRole::cel_refinement, 0.02),
              point("CEL 10", "L2", ReferenceRole::cel_refinement, 0.01),
              point("not run", "L3"),
              point("failed", "L3")};
  for (auto& p : q.points) p.quantity = "arching";
  std::map<std::string, BenchRun> runs;
  runs[point_id(q.points[0])] = label_run("arching", "arched", 0.002);
  runs[point_id(q.points[1])] = label_run("arching", "flowing", 0.002);
  runs[point_id(q.points[2])] = label_run("arching", "flowing", 2.0);
  runs[point_id(q.points[3])] = label_run("arching", "arched", 15.0);
  runs[point_id(q.points[5])] = label_run("other", "x", 1.0);
  runs[point_id(q.points[5])].status = "failed: blew up";
  const BenchQuestionTable t = tabulate(q, runs);
  EXPECT_EQ(t.reference.label, "arched");
  EXPECT_EQ(*t.answers[0].error, 0.0);
  EXPECT_EQ(*t.answers[1].error, 1.0);
  EXPECT_EQ(*t.answers[2].error, 1.0);
  EXPECT_FALSE(t.answers[3].error);  // the reference's own run has no error to show
  EXPECT_FALSE(t.answers[4].error);
  EXPECT_EQ(t.answers[4].label, "not run");
  EXPECT_FALSE(t.answers[5].error);
  EXPECT_FALSE(t.answers[5].pareto);
  EXPECT_FALSE(error_against_time_chart(t));  // labels have no log-log chart
  const std::string csv = bench_csv({t});
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);  // header + one row per point
  EXPECT_NE(csv.find(",failed: blew up,"), std::string::npos);
}

// A saved run reads back for the same invocation and inputs only; a damaged file is not read; a
// run saved before inputs were fingerprinted counts only where asked (a simulation) and when it
// has results.
TEST(BenchRunFile, ReadsBackForTheSameInvocationAndInputsOnly) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("feedflow_bench_run_" + std::to_string(::getpid()));
  BenchRun r = number_run("mass_flow_rate", 4.5, 4.0, 5.5, 0.25);
  r.invocation = "design cases/pilot_hopper.toml";
  r.cores = 2;
  r.inputs = "0123456789abcdef";
  save_bench_run(dir, r);
  const auto back = saved_bench_run(dir, r.invocation, r.inputs, false);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->wall_seconds, 0.25);
  EXPECT_EQ(back->cores, 2);
  EXPECT_EQ(back->results, r.results);
  EXPECT_FALSE(saved_bench_run(dir, "design cases/other.toml", r.inputs, false));
  EXPECT_FALSE(
      saved_bench_run(dir, r.invocation, "fedcba9876543210", true));  // the material changed
  r.inputs.clear();
  save_bench_run(dir, r);
  EXPECT_FALSE(saved_bench_run(dir, r.invocation, "0123456789abcdef", false));
  EXPECT_TRUE(saved_bench_run(dir, r.invocation, "0123456789abcdef", true));
  r.results = nullptr;  // failed before its case file was read: no fingerprint, no results
  r.status = "failed: ./cases/pilot_hopper.toml: no such case file";
  save_bench_run(dir, r);
  EXPECT_FALSE(saved_bench_run(dir, r.invocation, "0123456789abcdef", true));
  std::ofstream(dir / "run.json") << "{ damaged";
  EXPECT_FALSE(saved_bench_run(dir, r.invocation, "", true));
  std::filesystem::remove_all(dir);
}

// The inputs' fingerprint follows the material: a design point's changes with the material's
// [calibration], a simulation's does not (no solver reads it), both with the case's values.
TEST(BenchRunFile, FingerprintFollowsWhatTheAnswerReads) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("feedflow_bench_fp_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "cases" / "materials");
  std::filesystem::copy_file(std::filesystem::path(FEEDFLOW_SOURCE_DIR) / "cases" /
                                 "pilot_hopper.toml",
                             dir / "cases" / "pilot_hopper.toml");
  const auto pine =
      std::filesystem::path(FEEDFLOW_SOURCE_DIR) / "cases" / "materials" / "loblolly_pine.toml";
  std::filesystem::copy_file(pine, dir / "cases" / "materials" / "loblolly_pine.toml");
  BenchQuestion q{"rate", "rate", "cases/pilot_hopper.toml", {}, false, {}, {}, {}};
  BenchPoint design, cel;
  cel.solver = Solver::cel;
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);  // the material is found in ./cases/materials
  const std::string d0 = bench_inputs_fingerprint(q, design, "."),
                    c0 = bench_inputs_fingerprint(q, cel, ".");
  const std::string plain = without_calibration(
      material_text(load_case((dir / "cases" / "pilot_hopper.toml").string()).material));
  std::ofstream(dir / "cases" / "materials" / "loblolly_pine.toml")
      << plain
      << "\n[calibration]\nagainst = \"cel\"\nrung = \"test\"\nscene = \"pilot_hopper\"\ngeometry "
         "= \"wedge\"\n"
         "density_model = \"compressible\"\ncommit = \"none\"\ndate = \"2026-12-02\"\n"
         "[calibration.discharge.brown]\ncoefficients = { factor = 1.5 }\n";
  const std::string d1 = bench_inputs_fingerprint(q, design, "."),
                    c1 = bench_inputs_fingerprint(q, cel, ".");
  std::ofstream(dir / "cases" / "pilot_hopper.toml", std::ios::app)
      << "\n# a comment changes the case's text\n";
  const std::string c2 = bench_inputs_fingerprint(q, cel, ".");
  std::filesystem::current_path(cwd);
  EXPECT_EQ(d0.size(), 16u);
  EXPECT_NE(d0, d1);
  EXPECT_EQ(c0, c1);
  EXPECT_NE(c1, c2);
  std::filesystem::remove_all(dir);
}

// The answer of a CEL run, without what depends on the machine (wall times, rates per second)
// or names the run.
nlohmann::ordered_json physics_of(const BenchRun& run) {
  nlohmann::ordered_json j = run.results;
  for (const char* wall : {"run_wall_time", "cell_updates_per_second"}) j.erase(wall);
  for (auto& [key, e] : j.items())
    for (const char* text : {"model", "source"}) e.erase(text);
  return j;
}

// The pilot hopper's rate at 120 mm on 20 mm CEL cells for 0.3 s: a bench point of seconds.
BenchQuestion wide_outlet_rate() {
  return {"rate", "rate", "cases/pilot_hopper.toml", {"hopper.outlet_width=120mm"}, false, {}, {}, {}};
}
BenchPoint coarse_cel_point() {
  BenchPoint cel = point("CEL cells 20mm", "L2");
  cel.solver = Solver::cel;
  cel.sets = {"cel.cell_size=20mm"};
  cel.time = 0.3;
  return cel;
}

// The point run in `folder` with Ctrl-C after `seconds` of wall time.
BenchRun run_cut_by_ctrl_c(const BenchQuestion& q, const BenchPoint& p, const std::filesystem::path& root,
                           const std::filesystem::path& folder, double seconds) {
  std::thread ctrl_c([&] {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    request_interrupt();
  });
  bool made = false;
  const BenchRun run = run_or_read_back(q, p, root, folder, made);
  ctrl_c.join();
  clear_interrupt_request();
  return run;
}

// Whether the run in `folder` says in its run.log that it went on from its kept checkpoint.
::testing::AssertionResult continued_from_kept_checkpoint(const std::filesystem::path& folder) {
  std::ifstream log(folder / "run.log");
  const std::string said((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  if (said.find("restarted from " + interrupted_checkpoint(folder).string()) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << said;
}

// A simulation cut short (Ctrl-C part way) keeps its checkpoint, and the same point run again
// continues from it to the answer of a run never cut, with the two parts' wall times added;
// the answer is then read back, and the checkpoint of the cut is gone.
TEST(BenchRunFile, ACutRunContinuesFromItsCheckpoint) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("feedflow_bench_cut_" + std::to_string(::getpid()));
  const std::filesystem::path root = FEEDFLOW_SOURCE_DIR;
  const BenchQuestion q = wide_outlet_rate();
  const BenchPoint cel = coarse_cel_point();
  bool made = false;
  const auto t0 = std::chrono::steady_clock::now();
  const BenchRun straight = run_or_read_back(q, cel, root, dir / "straight", made);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(straight.done()) << straight.status;
  int tried = 0, continued = 0;
  for (double fraction : {0.5, 0.25, 0.75}) {  // a loaded machine shifts the phases: try others
    if (continued > 0) break;
    const auto cut = dir / ("cut" + std::to_string(++tried));
    const BenchRun first = run_cut_by_ctrl_c(q, cel, root, cut, fraction * wall);
    if (first.status != "interrupted") continue;  // ended before the signal
    ASSERT_TRUE(std::filesystem::exists(interrupted_checkpoint(cut)));
    EXPECT_FALSE(saved_run_of(q, cel, root, cut));  // not an answer to read back
    const BenchRun second = run_or_read_back(q, cel, root, cut, made);
    EXPECT_TRUE(made);
    ASSERT_TRUE(second.done()) << second.status;
    EXPECT_TRUE(continued_from_kept_checkpoint(cut));
    EXPECT_EQ(physics_of(second), physics_of(straight)) << "cut after " << fraction * wall << " s";
    EXPECT_GT(second.wall_seconds, first.wall_seconds);
    EXPECT_FALSE(std::filesystem::exists(interrupted_checkpoint(cut)));
    run_or_read_back(q, cel, root, cut, made);
    EXPECT_FALSE(made);
    ++continued;
  }
  EXPECT_GE(continued, 1);
  std::filesystem::remove_all(dir);
}

// A run killed outright (no Ctrl-C) leaves its run.json marked cut short from its start, and the
// checkpoint it wrote on the way as the scene's checkpoint.h5: the next call takes that
// checkpoint and ends with the uninterrupted run's answer. (The kill is staged: a Ctrl-C's
// checkpoint put back where a checkpoint on the way lies.)
TEST(BenchRunFile, ARunKilledOutrightContinuesFromItsCheckpointOnTheWay) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("feedflow_bench_killed_" + std::to_string(::getpid()));
  const std::filesystem::path root = FEEDFLOW_SOURCE_DIR;
  const BenchQuestion q = wide_outlet_rate();
  const BenchPoint cel = coarse_cel_point();
  bool made = false;
  // The first status run.json shows while the straight run goes is "interrupted".
  std::string first_seen;
  std::atomic<bool> finished{false};
  std::thread watch([&] {
    while (!finished && first_seen.empty()) {
      std::ifstream in(dir / "straight" / "run.json");
      if (in) first_seen = nlohmann::json::parse(in, nullptr, false).value("status", "");
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  const auto t0 = std::chrono::steady_clock::now();
  const BenchRun straight = run_or_read_back(q, cel, root, dir / "straight", made);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  finished = true;
  watch.join();
  ASSERT_TRUE(straight.done()) << straight.status;
  EXPECT_EQ(first_seen, "interrupted");
  int continued = 0;
  for (double fraction : {0.5, 0.25, 0.75}) {
    if (continued > 0) break;
    const auto cut = dir / ("cut" + std::to_string(fraction));
    const BenchRun first = run_cut_by_ctrl_c(q, cel, root, cut, fraction * wall);
    if (first.status != "interrupted") continue;
    std::filesystem::rename(interrupted_checkpoint(cut),
                            scene_checkpoint_path(cut));  // as a kill leaves it
    const BenchRun second = run_or_read_back(q, cel, root, cut, made);
    ASSERT_TRUE(second.done()) << second.status;
    EXPECT_TRUE(continued_from_kept_checkpoint(cut));
    EXPECT_EQ(physics_of(second), physics_of(straight));
    ++continued;
  }
  EXPECT_GE(continued, 1);
  // The checkpoint beside a finished run is not adopted.
  adopt_checkpoint_of_killed_run(dir / "straight", bench_invocation(q, cel),
                                 bench_inputs_fingerprint(q, cel, root));
  EXPECT_FALSE(std::filesystem::exists(interrupted_checkpoint(dir / "straight")));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace feedflow
