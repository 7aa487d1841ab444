// The judges read estimates of any rung: hand-made simulation-like estimate sets (what a DEM or
// CEL run reports) are judged by the same rules as the reduced models', each reason naming its
// quantity with the numbers, and the reduced models' own estimates give the design check's
// verdicts.
#include <gtest/gtest.h>

#include "designer/case/case_loader.hpp"
#include "designer/design/design_check.hpp"
#include "designer/design/judge.hpp"

namespace feedflow {
namespace {

Estimate number(double value, std::string unit, std::optional<double> low, std::optional<double> high,
                Rung rung = Rung::L3) {
  return Estimate{value, std::move(unit), low, high, "hand-made", rung, ""};
}
Estimate label(std::string value, Rung rung = Rung::L3) {
  return Estimate{std::move(value), "", std::nullopt, std::nullopt, "hand-made", rung, ""};
}

const Finding* finding_on(const Verdict& v, const std::string& quantity) {
  for (const auto& f : v.findings)
    if (f.quantity == quantity) return &f;
  return nullptr;
}

std::string verdict_reasons(const Verdict& v) {
  std::string s;
  for (const auto& r : v.reasons) s += r + "\n";
  return s;
}

// A DEM hopper run that arched fails, the finding naming `arching`; the flow pattern of a run
// that arched is not judged (nothing flowed to show it).
TEST(Judge, ArchedHopperFailsNamingArching) {
  const Case c = load_case("cases/pilot_hopper.toml");
  const Estimates dem = {{"mass_flow_rate", number(0.0, "kg/s", 0.0, 0.0)},
                         {"arching", label("arched")},
                         {"flow_pattern", label("funnel")}};
  const Verdict v = judge(c, dem);
  EXPECT_EQ(v.status, VerdictStatus::fail) << verdict_reasons(v);
  const Finding* arching = finding_on(v, "arching");
  ASSERT_NE(arching, nullptr) << verdict_reasons(v);
  EXPECT_EQ(arching->status, VerdictStatus::fail);
  const Finding* pattern = finding_on(v, "flow_pattern");
  ASSERT_NE(pattern, nullptr);
  EXPECT_FALSE(pattern->status.has_value()) << pattern->text;  // a note: "mass required" is not failed on it
}

// A flowing DEM run in mass flow passes; quantities the run does not give (B_c, interlocking,
// the pattern's margin) are not mentioned.
TEST(Judge, FlowingHopperPassesOnWhatItMeasured) {
  const Case c = load_case("cases/pilot_hopper.toml");
  const Estimates dem = {{"mass_flow_rate", number(2.9, "kg/s", 2.7, 3.1)},
                         {"arching", label("flowing")},
                         {"flow_pattern", label("mass")}};
  const Verdict v = judge(c, dem);
  EXPECT_EQ(v.status, VerdictStatus::pass) << verdict_reasons(v);
  EXPECT_EQ(v.findings.size(), 2u)
      << verdict_reasons(v);  // arching and flow pattern; no throughput target
  EXPECT_EQ(finding_on(v, "critical_outlet_width"), nullptr);
  EXPECT_EQ(finding_on(v, "mechanical_arching_width"), nullptr);
}

// A q_m band reaching below the required throughput is marginal, one entirely below it fails;
// both findings carry the rate, its band and the requirement in kg/s.
TEST(Judge, ThroughputBandBelowTheRequirement) {
  Case c = load_case("cases/pilot_hopper.toml");
  c.design.required_throughput = 3.0;
  const Verdict inside = judge(c, {{"mass_flow_rate", number(3.2, "kg/s", 2.8, 3.6)}});
  EXPECT_EQ(inside.status, VerdictStatus::marginal) << verdict_reasons(inside);
  const Finding* q = finding_on(inside, "mass_flow_rate");
  ASSERT_NE(q, nullptr);
  EXPECT_EQ(q->unit, "kg/s");
  EXPECT_DOUBLE_EQ(*q->value, 3.2);
  EXPECT_DOUBLE_EQ(*q->low, 2.8);
  EXPECT_DOUBLE_EQ(*q->high, 3.6);
  EXPECT_DOUBLE_EQ(*q->limit, 3.0);
  EXPECT_NE(q->text.find("3 kg/s"), std::string::npos) << q->text;
  const Verdict below = judge(c, {{"mass_flow_rate", number(2.5, "kg/s", 2.2, 2.8)}});
  EXPECT_EQ(below.status, VerdictStatus::fail) << verdict_reasons(below);
  EXPECT_EQ(finding_on(below, "mass_flow_rate")->status, VerdictStatus::fail);
}

// A DEM drum whose measured regime is not the required one fails naming `regime`; an
// unmeasured regime is a note and judges nothing.
TEST(Judge, MeasuredRegimeOtherThanRequiredFails) {
  const Case c = load_case("cases/rotating_drum_20rpm.toml");  // rolling required
  const Verdict v = judge(c, {{"dynamic_angle_of_repose", number(38.0, "deg", 36.0, 40.0)},
                              {"regime", label("cascading")}});
  EXPECT_EQ(v.status, VerdictStatus::fail) << verdict_reasons(v);
  ASSERT_NE(finding_on(v, "regime"), nullptr);
  EXPECT_EQ(finding_on(v, "regime")->status, VerdictStatus::fail);
  EXPECT_NE(verdict_reasons(v).find("rolling required"), std::string::npos) << verdict_reasons(v);
  const Verdict rolling = judge(c, {{"regime", label("rolling")}});
  EXPECT_EQ(rolling.status, VerdictStatus::pass) << verdict_reasons(rolling);
  const Verdict unmeasured = judge(c, {{"regime", label("not measured")}});
  EXPECT_EQ(unmeasured.status, VerdictStatus::unknown) << verdict_reasons(unmeasured);
  EXPECT_EQ(unmeasured.findings.size(), 1u);
}

// A simulated mid-ramp deposit is held against the allowed thickness by the same rule as the
// reduced models' stopping thickness: the band's top decides a pass, the value a fail.
TEST(Judge, SimulatedDepositAgainstTheAllowedThickness) {
  Case c = load_case("cases/inclined_plane_37.toml");
  c.design.max_stopping_thickness = 5e-3;
  const auto deposit = [](double v, double lo, double hi) {
    return Estimates{{"deposit_thickness_mid_ramp", number(v, "m", lo, hi)}};
  };
  EXPECT_EQ(judge(c, deposit(3e-3, 2e-3, 4e-3)).status, VerdictStatus::pass);
  const Verdict inside = judge(c, deposit(4e-3, 3e-3, 6e-3));
  EXPECT_EQ(inside.status, VerdictStatus::marginal) << verdict_reasons(inside);
  EXPECT_DOUBLE_EQ(*finding_on(inside, "deposit_thickness_mid_ramp")->limit, 5e-3);
  EXPECT_EQ(judge(c, deposit(6e-3, 4e-3, 7e-3)).status, VerdictStatus::fail);
}

// Nothing to judge, nothing said: an empty estimate list leaves the verdict unknown.
TEST(Judge, SaysNothingOfAbsentQuantities) {
  for (const char* file : {"cases/pilot_hopper.toml", "cases/inclined_plane_37.toml", "cases/rotating_drum_20rpm.toml"}) {
    const Verdict v = judge(load_case(file), {});
    EXPECT_EQ(v.status, VerdictStatus::unknown) << file;
    EXPECT_TRUE(v.reasons.empty()) << file << ": " << verdict_reasons(v);
  }
}

// On the reduced models' estimates the judge gives the design check's verdicts on every shipped
// case (pass on all four, as before the split), and every judged reason names its quantity.
TEST(Judge, ReducedModelEstimatesGiveTheShippedVerdicts) {
  for (const char* file : {"cases/pilot_hopper.toml", "cases/inclined_plane_29_5.toml", "cases/inclined_plane_37.toml",
                           "cases/rotating_drum_20rpm.toml"}) {
    const Case c = load_case(file);
    const DesignRecord r = design_check(c);
    EXPECT_EQ(r.verdict.status, VerdictStatus::pass) << file << "\n" << verdict_reasons(r.verdict);
    EXPECT_EQ(judge(c, r.results).status, r.verdict.status) << file;
    for (const auto& f : r.verdict.findings) {
      if (!f.status) continue;
      EXPECT_FALSE(f.quantity.empty()) << f.text;
      EXPECT_NE(find_estimate(r.results, f.quantity), nullptr) << f.quantity;
    }
  }
}

// The outlet's reason states the rule applied: PASS above the safety factor times the top of the
// B_c band, MARGINAL from the safety factor times B_c itself, with both widths.
TEST(Judge, OutletReasonStatesThePassRule) {
  const Case c = load_case("cases/pilot_hopper.toml");
  const DesignRecord r = design_check(c);
  const Finding* outlet = finding_on(r.verdict, "critical_outlet_width");
  ASSERT_NE(outlet, nullptr);
  const Estimate& bc = *find_estimate(r.results, "critical_outlet_width");
  EXPECT_DOUBLE_EQ(*outlet->high, *bc.high);
  EXPECT_DOUBLE_EQ(*outlet->limit, 0.060 / 1.2);  // the largest B_c the outlet tolerates
  EXPECT_NE(outlet->text.find("PASS needs outlet >= 1.2 x B_c band top = 50.6 mm"), std::string::npos) << outlet->text;
  EXPECT_NE(outlet->text.find("MARGINAL from 1.2 x B_c = 36.7 mm"), std::string::npos) << outlet->text;
}

}  // namespace
}  // namespace feedflow
