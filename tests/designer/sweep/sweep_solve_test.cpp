// `--solve-for`: the boundary a solve finds is the one the design check draws, to the tolerance,
// on the meeting side, with the check that sets it.
#include <gtest/gtest.h>

#include <filesystem>

#include <omp.h>

#include "designer/design/design_check.hpp"
#include "designer/sweep/sweep_grid.hpp"
#include "designer/sweep/sweep_solve.hpp"

namespace feedflow {
namespace {

SweepRequest pilot_solve(const std::string& solve_for, const std::string& target, double tolerance,
                         std::vector<std::string> fixed = {}) {
  SweepRequest r;
  const std::filesystem::path cases = std::filesystem::path(FEEDFLOW_SOURCE_DIR) / "cases";
  r.parsed = parse_case((cases / "pilot_hopper.toml").string());
  r.materials = MaterialLibrary::standard(cases);
  for (const auto& f : fixed) r.fixed.push_back(parse_set_override(f));
  SweepSolve s;
  s.axis = parse_sweep_axis(solve_for, "--solve-for");
  s.target = parse_sweep_target(target);
  check_sweep_target(s.target, answer_overrides(r, r.fixed).results);
  s.tolerance = tolerance;
  r.solve = s;
  return r;
}

// The design check at one value of the solved key.
SweepPoint at(const SweepRequest& r, double si) {
  std::vector<SetOverride> sets = r.fixed;
  sets.push_back({r.solve->axis.case_key, axis_value(r.solve->axis, si).text});
  return answer_overrides(r, sets);
}

// The smallest passing outlet is the arching rule's analytic boundary, safety factor x the top of
// the critical width's band (hopper_judge), to the tolerance, and it passes while a tolerance
// below it does not; MARGINAL starts at safety factor x B_c.
TEST(SweepSolve, SmallestPassingOutletIsTheArchingRulesBoundary) {
  const double tol = 1e-5;  // 0.01 mm
  const SweepRequest r = pilot_solve("hopper.outlet_width=20..100mm:9", "pass", tol);
  const SweepPoint p = solve_point(r, {});
  ASSERT_TRUE(p.done) << p.error;
  const SweepSolution& s = *p.solution;
  ASSERT_EQ(s.outcome, SweepSolution::Outcome::solved);
  EXPECT_TRUE(s.smallest);
  EXPECT_EQ(p.verdict, VerdictStatus::pass);
  EXPECT_NE(at(r, s.value - tol).verdict, VerdictStatus::pass);
  ASSERT_EQ(s.beyond_governing, std::vector<std::string>{"critical_outlet_width"});
  const Estimate* bc = find_estimate(p.results, "critical_outlet_width");
  ASSERT_TRUE(bc && bc->high);
  EXPECT_NEAR(s.value, 1.2 * *bc->high, tol);
  EXPECT_LE(s.bracket_high - s.bracket_low, tol);
  // MARGINAL begins at safety factor x B_c itself, the band's other edge.
  ASSERT_TRUE(s.marginal_from.has_value());
  EXPECT_NEAR(*s.marginal_from, 1.2 * std::get<double>(bc->value), tol);
  EXPECT_LT(s.evaluations, 9 + 2 * 20);  // the scan and two bisections, not a fine scan
}

// The largest semi-angle with mass flow is the mass-flow limit angle the check reports.
TEST(SweepSolve, LargestMassFlowAngleIsTheLimitAngle) {
  const double tol = 1e-5;  // rad
  const SweepRequest r = pilot_solve("hopper.semi_angle=5..65deg/5deg", "flow_pattern=mass", tol);
  const SweepPoint p = solve_point(r, {});
  ASSERT_EQ(p.solution->outcome, SweepSolution::Outcome::solved) << p.error;
  EXPECT_FALSE(p.solution->smallest);
  const Estimate* limit = find_estimate(p.results, "mass_flow_limit_angle");  // in deg
  ASSERT_NE(limit, nullptr);
  EXPECT_NEAR(p.solution->value * 180.0 / 3.141592653589793, std::get<double>(limit->value),
              2 * tol * 180.0 / 3.141592653589793);
}

// The outlet that delivers a throughput: q_m crosses it inside the final bracket.
TEST(SweepSolve, OutletForAThroughputBracketsTheCrossing) {
  const double tol = 1e-6;
  const SweepRequest r =
      pilot_solve("hopper.outlet_width=20..200mm:10", "mass_flow_rate=5kg/s", tol);
  const SweepPoint p = solve_point(r, {});
  ASSERT_EQ(p.solution->outcome, SweepSolution::Outcome::solved) << p.error;
  auto rate = [](const SweepPoint& q) {
    return std::get<double>(find_estimate(q.results, "mass_flow_rate")->value);
  };
  EXPECT_GE(rate(p), 5.0);
  EXPECT_LT(rate(at(r, p.solution->value - tol)), 5.0);
}

// A range that cannot meet the target is "never met", with the nearest value's reason; a range
// that meets it throughout says the boundary lies beyond it.
TEST(SweepSolve, RangesThatDoNotCrossSaySo) {
  const SweepRequest never = pilot_solve("hopper.outlet_width=10..20mm:3", "pass", 1e-4);
  const SweepPoint n = solve_point(never, {});
  EXPECT_FALSE(n.done);
  EXPECT_EQ(n.solution->outcome, SweepSolution::Outcome::never_met);
  EXPECT_NE(n.error.find("no hopper.outlet_width in 10 mm .. 20 mm passes; nearest at 20 mm"),
            std::string::npos)
      << n.error;
  const SweepRequest always = pilot_solve("hopper.outlet_width=0.2..0.4m:3", "pass", 1e-4);
  const SweepPoint a = solve_point(always, {});
  EXPECT_TRUE(a.done);
  EXPECT_EQ(a.solution->outcome, SweepSolution::Outcome::met_everywhere);
}

// Solved over a grid of the other keys on two threads: each point's answer is the arching
// rule's boundary at its semi-angle, as solved alone.
TEST(SweepSolve, GridOfSolvesOnThreads) {
  SweepRequest r = pilot_solve("hopper.outlet_width=20..100mm:9", "pass", 1e-5);
  r.axes.push_back(parse_sweep_axis("hopper.semi_angle=15..30deg/5deg"));
  SilentProgress quiet;
  omp_set_num_threads(2);
  const auto points = run_grid(r, quiet);
  omp_set_num_threads(1);
  ASSERT_EQ(points.size(), 4u);
  for (std::size_t k = 0; k < points.size(); ++k) {
    ASSERT_EQ(points[k].solution->outcome, SweepSolution::Outcome::solved) << points[k].error;
    EXPECT_EQ(points[k].solution->value, solve_point(r, {k}).solution->value);
    const Estimate* bc = find_estimate(points[k].results, "critical_outlet_width");
    EXPECT_NEAR(points[k].solution->value, 1.2 * *bc->high, 1e-5);
  }
}

}  // namespace
}  // namespace feedflow
