// `--target`: the conditions a solve looks for, read and checked against a design check's
// results, with units converted into the result's own.
#include <gtest/gtest.h>

#include "designer/sweep/sweep_target.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

Estimates results() {
  Estimates r;
  r.emplace_back("critical_outlet_width", Estimate{0.0306, "m", 0.024, 0.0422, "", Rung::L0, "mm"});
  r.emplace_back("mass_flow_rate", Estimate{2.84, "kg/s", 2.15, 4.77, "", Rung::L0, ""});
  r.emplace_back("flow_pattern", Estimate{std::string("mass"), "", {}, {}, "", Rung::L0, ""});
  return r;
}

std::string target_refusal(const std::string& text, bool check = false) {
  try {
    SweepTarget t = parse_sweep_target(text);
    if (check) check_sweep_target(t, results());
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "--target");
    return e.what();
  }
  return "";
}

// A verdict target meets at its worst allowed status; not-fail lets MARGINAL through.
TEST(SweepTarget, VerdictTargets) {
  const SweepTarget pass = parse_sweep_target("pass"), not_fail = parse_sweep_target("not-fail");
  EXPECT_TRUE(*meets_target(pass, VerdictStatus::pass, {}));
  EXPECT_FALSE(*meets_target(pass, VerdictStatus::marginal, {}));
  EXPECT_TRUE(*meets_target(not_fail, VerdictStatus::marginal, {}));
  EXPECT_FALSE(*meets_target(not_fail, VerdictStatus::fail, {}));
  EXPECT_FALSE(*meets_target(not_fail, VerdictStatus::unknown, {}));
}

// A value written in mm is compared with a result kept in m; .low reads the band's low end.
TEST(SweepTarget, NumbersAreConvertedIntoTheResultsUnit) {
  SweepTarget t = parse_sweep_target("critical_outlet_width<=40mm");
  check_sweep_target(t, results());
  EXPECT_NEAR(t.value, 0.040, 1e-15);
  EXPECT_TRUE(*meets_target(t, VerdictStatus::fail, results()));  // 30.6 mm <= 40 mm
  SweepTarget low = parse_sweep_target("mass_flow_rate.low >= 2.5 kg/s");
  check_sweep_target(low, results());
  EXPECT_FALSE(*meets_target(low, VerdictStatus::pass, results()));  // 2.15 < 2.5
  SweepTarget value = parse_sweep_target("mass_flow_rate=2.5kg/s");
  check_sweep_target(value, results());
  EXPECT_TRUE(*meets_target(value, VerdictStatus::pass, results()));  // 2.84 past the crossing
  SweepTarget word = parse_sweep_target("flow_pattern!=funnel");
  check_sweep_target(word, results());
  EXPECT_TRUE(*meets_target(word, VerdictStatus::pass, results()));
}

// Faults name --target and say what was expected.
TEST(SweepTarget, BadTargetsAreRefused) {
  EXPECT_NE(target_refusal("passes").find("expected pass"), std::string::npos);
  EXPECT_NE(target_refusal("mass_flow_rate!=5kg/s").find("compared with >="), std::string::npos);
  EXPECT_NE(target_refusal("flow_pattern>=mass").find("compared with = or !="), std::string::npos);
  EXPECT_NE(target_refusal("mass_flowrate>=5kg/s", true).find("did you mean \"mass_flow_rate\""),
            std::string::npos);
  EXPECT_NE(target_refusal("mass_flow_rate>=5", true).find("give the value a unit"),
            std::string::npos);
  EXPECT_NE(target_refusal("mass_flow_rate>=5mm", true).find("measures length"), std::string::npos);
  EXPECT_NE(target_refusal("flow_pattern>=5", true).find("is a word"), std::string::npos);
  EXPECT_NE(target_refusal("critical_outlet_width=mass", true).find("is a number"),
            std::string::npos);
}

}  // namespace
}  // namespace feedflow
