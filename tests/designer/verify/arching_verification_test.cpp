// The plan of an arching verification on the particle rung (designer/verify/arching_verification):
// the contact law decides what the DEM can verify, and the band it searches.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "designer/case/case_loader.hpp"
#include "designer/design/design_check.hpp"
#include "designer/verify/arching_verification.hpp"
#include "designer/verify/design_verification.hpp"
#include "kept_runs.hpp"
#include "models/core/errors.hpp"
#include "reports/results_json.hpp"

namespace feedflow {
namespace {

ArchingVerificationPlan plan_for(const std::vector<SetOverride>& sets, double tolerance) {
  const Case c = load_case("cases/pilot_hopper.toml", sets);
  return plan_arching_verification(c, design_check(c, ModelChoices{}), tolerance);
}

// The seed's hysteretic law with contacts that pull (cohesion k_nc): the DEM can form cohesive
// arches, so it searches the reduced B_c band (20.48-42.18 mm at 30 deg); 1 mm takes the design
// outlet's run and 2 + ceil(log2(21.7)) = 7 widths.
TEST(ArchingVerification, CohesiveLawSearchesTheReducedCriticalWidthBand) {
  const auto plan = plan_for({{"dem.cohesion", "k_nc"}}, 0.001);
  EXPECT_EQ(plan.law, "hysteretic_nonlinear2 + k_nc cohesion");
  EXPECT_EQ(plan.quantity, "critical_outlet_width");
  EXPECT_NEAR(plan.low, 0.02048, 1e-5);
  EXPECT_NEAR(plan.high, 0.04218, 1e-5);
  EXPECT_EQ(plan.runs, 8);
}

// The same law as the seed's software runs it (cohesion none: the force clipped at zero) cannot
// pull, so only interlocking arches: 3-8 diameters of its 3 mm spheres (9-24 mm, 1 + 2 + 4 runs);
// the case with contacts that pull is the one a cohesive B_c needs.
TEST(ArchingVerification, SeedLawWithoutCohesionSearchesTheInterlockingRange) {
  const Case c = load_case("cases/pilot_hopper.toml", {});
  const auto plan = plan_arching_verification(c, design_check(c, ModelChoices{}), 0.001);
  EXPECT_EQ(plan.law, "hysteretic_nonlinear2");
  EXPECT_EQ(plan.quantity, "mechanical_arching_width");
  EXPECT_NEAR(plan.low, 0.009, 1e-12);
  EXPECT_NEAR(plan.high, 0.024, 1e-12);
  EXPECT_EQ(plan.runs, 1 + 2 + 4);
  const auto cohesive = with_cohesive_contacts(c);
  ASSERT_TRUE(cohesive.has_value());
  EXPECT_EQ(cohesive->dem.cohesion, "k_nc");
  EXPECT_FALSE(with_cohesive_contacts(*cohesive).has_value());  // a case's own choice stays
  const std::vector<SetOverride> hertz{{"dem.normal_law", "hertz"}};
  EXPECT_FALSE(with_cohesive_contacts(load_case("cases/pilot_hopper.toml", hertz)).has_value());
}

// Hertz has no cohesion: only interlocking arches, at 3-8 diameters of the DEM's own spheres
// (R = 3 mm: 18-48 mm), whatever the material's d90.
TEST(ArchingVerification, LawWithoutCohesionSearchesTheInterlockingRangeOfItsSpheres) {
  const auto plan =
      plan_for({{"dem.normal_law", "hertz"}, {"material.dem.particle.radius", "3 mm"}}, 0.002);
  EXPECT_EQ(plan.quantity, "mechanical_arching_width");
  EXPECT_DOUBLE_EQ(plan.sphere_diameter, 0.006);
  EXPECT_NEAR(plan.low, 0.018, 1e-12);
  EXPECT_NEAR(plan.high, 0.048, 1e-12);
  EXPECT_EQ(plan.runs, 1 + 2 + 4);  // log2(30 / 2) = 3.9
  EXPECT_THROW(plan_for({}, 0.0), InputError);
}

// A bracket on the particle rung replaces B_c in SI with its display unit, and the verdict is
// judged on it: the pilot hopper's 45 mm outlet, MARGINAL on the reduced band (1.2 x 42.2 mm =
// 50.6 mm), passes once the DEM arches at 26.8 mm and flows at 29.5 mm (1.2 x 29.5 = 35.4 mm).
TEST(ArchingVerification, ABracketedWidthIsJudgedInMetres) {
  const Case c =
      load_case("cases/pilot_hopper.toml", std::vector<SetOverride>{{"hopper.outlet_width", "45mm"},
                                                                    {"dem.cohesion", "k_nc"}});
  DesignRecord record = design_check(c, ModelChoices{});
  EXPECT_EQ(record.verdict.status, VerdictStatus::marginal);
  const auto plan = plan_arching_verification(c, record, 0.0025);
  ArchingVerification v;
  v.at_design = OutletOutcome::flows;
  v.bisection.end = WidthBisection::End::bracketed;
  v.bisection.arches_at = 0.0268;
  v.bisection.flows_at = 0.0295;
  v.bisection.steps = {{0.045, OutletOutcome::flows},
                       {0.0268, OutletOutcome::arches},
                       {0.0295, OutletOutcome::flows}};
  apply_arching_verification(c, plan, v, record);
  const Estimate* bc = find_estimate(record.results, "critical_outlet_width");
  ASSERT_NE(bc, nullptr);
  EXPECT_EQ(bc->rung, Rung::L3);
  EXPECT_EQ(bc->unit, "m");
  EXPECT_EQ(bc->display_unit, "mm");
  EXPECT_DOUBLE_EQ(*bc->high, 0.0295);
  EXPECT_EQ(record.verdict.status, VerdictStatus::pass);
}

// Runs kept from an earlier call cost nothing: with the twin's design outlet (10 mm, 60 s) and
// the bisection's first two widths (48 mm flows, 18 mm arches) kept, a 1 s budget is refused
// for the 4 runs still to make (7 planned to 2 mm), not for all 6 of the bisection.
TEST(ArchingVerification, TheBudgetCountsOnlyTheRunsNotKept) {
  BenchQuestion q;
  q.case_file = "tests/data/dem_hopper_twin.toml";
  q.sets = {"hopper.outlet_width=10mm"};
  const std::filesystem::path runs =
      std::filesystem::temp_directory_path() / ("feedflow_kept_runs_" + std::to_string(::getpid()));
  std::filesystem::remove_all(runs);
  testing::lay_down_run(q, BenchPoint{}, runs, 0.010, "arched", 60.0, "aaaa");
  testing::lay_down_run(q, BenchPoint{}, runs, 0.048, "flowing", 50.0, "aaaa");
  testing::lay_down_run(q, BenchPoint{}, runs, 0.018, "arched", 40.0, "aaaa");
  const std::string case_file =
      (std::filesystem::path(FEEDFLOW_SOURCE_DIR) / q.case_file).lexically_normal().string();
  const Case c = load_case(case_file, std::vector<SetOverride>{{"hopper.outlet_width", "10mm"}});
  const auto plan = plan_arching_verification(c, design_check(c, ModelChoices{}), 0.002);
  ASSERT_EQ(plan.runs, 7);
  const ArchingVerification v =
      verify_arching(case_file, q.sets, std::get<Hopper>(c.equipment), plan, 1.0, runs, nullptr);
  EXPECT_EQ(v.at_design, OutletOutcome::arches);
  EXPECT_EQ(v.wall_seconds, 0.0);  // nothing was made
  EXPECT_NE(v.status.find("the bisection needs 4 more DEM runs (2 of its runs kept) of about "
                          "1 min 00 s each (4 min 00 s)"),
            std::string::npos)
      << v.status;
  std::filesystem::remove_all(runs);
}

// A conical hopper's flow pattern goes to the particle rung (the continuum's does not converge on
// a cone): the design outlet's DEM run, read back, puts its layer-method pattern in place of the
// reduced one (rung L3, the reduced one beside it) with what it was read from, and the verdict
// says verified or contradicted with both; a run that arched measured none and leaves it as it is.
TEST(ArchingVerification, TheDesignOutletsRunVerifiesAConesFlowPattern) {
  BenchQuestion q;
  q.case_file = "tests/data/dem_cone_twin.toml";
  const std::filesystem::path runs = std::filesystem::temp_directory_path() /
                                     ("feedflow_cone_pattern_" + std::to_string(::getpid()));
  std::filesystem::remove_all(runs);
  const std::string case_file =
      (std::filesystem::path(FEEDFLOW_SOURCE_DIR) / q.case_file).lexically_normal().string();
  const Case c = load_case(case_file, std::vector<SetOverride>{});
  const Hopper& h = std::get<Hopper>(c.equipment);
  const DesignRecord reduced = design_check(c, ModelChoices{});
  const auto reduced_pattern =
      std::get<std::string>(find_estimate(reduced.results, "flow_pattern")->value);
  const auto plan = plan_arching_verification(c, reduced, 0.002);
  const auto verified = [&](const nlohmann::ordered_json& measured, const std::string& arching) {
    std::filesystem::remove_all(runs);
    testing::lay_down_run(q, BenchPoint{}, runs, h.outlet_width, arching, 60.0, "aaaa", measured);
    const ArchingVerification v = verify_arching(case_file, {}, h, plan, 1.0, runs, nullptr);
    DesignRecord record = reduced;
    apply_arching_verification(c, plan, v, record);
    return record;
  };
  const std::string other = reduced_pattern == "mass" ? "funnel" : "mass";
  const DesignRecord r = verified({{"flow_pattern", {{"value", other}}},
                                   {"wall_to_centre_speed_ratio", {{"value", 0.05}}},
                                   {"fifo_index", {{"value", 0.41}}},
                                   {"stagnant_zone_width", {{"value", 30.0}}}},
                                  "flowing");
  const Estimate* dem = find_estimate(r.results, "flow_pattern");
  ASSERT_NE(dem, nullptr);
  EXPECT_EQ(dem->rung, Rung::L3);
  EXPECT_EQ(std::get<std::string>(dem->value), other);
  EXPECT_EQ(std::get<std::string>(find_estimate(r.results, "flow_pattern_reduced_model")->value),
            reduced_pattern);
  const std::string said = "flow pattern contradicted on the particle rung (DEM, " + plan.law +
                           " law): reduced " + reduced_pattern + ", DEM " + other;
  bool found = false;
  for (const auto& reason : r.verdict.reasons)
    found = found || (reason.find(said) != std::string::npos &&
                      reason.find("wall/centre speed 0.05, FIFO index 0.41, stagnant zone 30 mm") !=
                          std::string::npos);
  EXPECT_TRUE(found) << said;
  const DesignRecord same = verified({{"flow_pattern", {{"value", reduced_pattern}}}}, "flowing");
  EXPECT_EQ(find_estimate(same.results, "flow_pattern")->rung, Rung::L3);
  const DesignRecord arched = verified({}, "arched");
  EXPECT_EQ(find_estimate(arched.results, "flow_pattern")->rung, Rung::L0);
  EXPECT_EQ(find_estimate(arched.results, "flow_pattern_reduced_model"), nullptr);
  std::filesystem::remove_all(runs);
}

// A search cut short by its budget keeps its bracket so far (48 mm flows, 18 mm arches, laid down
// with the twin's 10 mm design outlet, which arched) beside the reduced width, unjudged; its
// record alone, on a machine without the runs, answers the design outlet and both widths, so the
// search starts inside them and asks for the 4 runs still to make (bisecting 18-48 mm to 2 mm);
// a record of another semi-angle, or of other spheres, is refused naming its key.
TEST(ArchingVerification, ASearchCutShortLeavesABracketToStartFrom) {
  BenchQuestion q;
  q.case_file = "tests/data/dem_hopper_twin.toml";
  q.sets = {"hopper.outlet_width=10mm"};
  const std::filesystem::path tmp = std::filesystem::temp_directory_path();
  const std::string pid = std::to_string(::getpid());
  VerificationRequest request;
  request.case_file =
      (std::filesystem::path(FEEDFLOW_SOURCE_DIR) / q.case_file).lexically_normal().string();
  request.sets = q.sets;
  request.mode = "dem";
  request.budget = "1 s";
  request.width_tolerance = "2 mm";
  request.runs = tmp / ("feedflow_arching_cut_" + pid);
  std::filesystem::remove_all(request.runs);
  testing::lay_down_run(q, BenchPoint{}, request.runs, 0.010, "arched", 60.0, "aaaa");
  testing::lay_down_run(q, BenchPoint{}, request.runs, 0.048, "flowing", 50.0, "aaaa");
  testing::lay_down_run(q, BenchPoint{}, request.runs, 0.018, "arched", 40.0, "aaaa");
  const Case c =
      load_case(request.case_file, std::vector<SetOverride>{{"hopper.outlet_width", "10mm"}});
  DesignRecord record = design_check(c, ModelChoices{});
  ASSERT_TRUE(verify_design(request, c, record));
  const std::string key = "mechanical_arching_width_dem_spheres";
  const Estimate* so_far = find_estimate(record.results, key + "_so_far");
  ASSERT_NE(so_far, nullptr) << record.verdict.reasons.back();
  EXPECT_EQ(so_far->rung, Rung::L3);
  EXPECT_NEAR(*so_far->low, 0.018, 1e-12);
  EXPECT_NEAR(*so_far->high, 0.048, 1e-12);
  EXPECT_EQ(find_estimate(record.results, key), nullptr);  // the bracket is not judged
  const std::filesystem::path saved = request.runs / "results.json";
  std::ofstream(saved) << to_json(record).dump(2);

  VerificationRequest elsewhere = request;
  elsewhere.runs = tmp / ("feedflow_arching_elsewhere_" + pid);
  std::filesystem::remove_all(elsewhere.runs);
  elsewhere.start_from = saved;
  DesignRecord again = design_check(c, ModelChoices{});
  ASSERT_TRUE(verify_design(elsewhere, c, again));
  EXPECT_EQ(find_estimate(again.results, "arching")->rung, Rung::L3);  // from the record
  const Estimate* resumed = find_estimate(again.results, key + "_so_far");
  ASSERT_NE(resumed, nullptr) << again.verdict.reasons.back();
  EXPECT_NEAR(*resumed->low, 0.018, 1e-9);
  EXPECT_NEAR(*resumed->high, 0.048, 1e-9);
  std::string notes;
  for (const auto& r : again.verdict.reasons) notes += r + "\n";
  EXPECT_NE(notes.find("the bisection needs 4 more DEM runs (2 of its runs kept)"),
            std::string::npos)
      << notes;
  EXPECT_NE(notes.find("--start-from"), std::string::npos) << notes;
  EXPECT_FALSE(std::filesystem::exists(elsewhere.runs));  // no run was made

  const Case steeper =
      load_case(request.case_file, std::vector<SetOverride>{{"hopper.outlet_width", "10mm"},
                                                            {"hopper.semi_angle", "20deg"}});
  DesignRecord other = design_check(steeper, ModelChoices{});
  try {
    verify_design(elsewhere, steeper, other);
    ADD_FAILURE() << "a record of another semi-angle started the search";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "inputs.hopper.semi_angle") << e.what();
  }
  // Nor one of other spheres (the record gives its radius).
  Case finer = c;
  finer.material.dem->particle.radius *= 0.5;
  DesignRecord finer_record = design_check(finer, ModelChoices{});
  try {
    verify_design(elsewhere, finer, finer_record);
    ADD_FAILURE() << "a record of other spheres started the search";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "inputs.material.dem.particle.radius") << e.what();
  }
  std::filesystem::remove_all(request.runs);
  std::filesystem::remove_all(elsewhere.runs);
}

}  // namespace
}  // namespace feedflow
