// The chute's judge (judge.hpp): whether the material flows and what stays on the ramp, from the
// estimates present.
#include "designer/design/estimate_reading.hpp"
#include "designer/design/judge.hpp"
#include "designer/design/verdict_builder.hpp"
#include "models/chute/pouliquen_law.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::string angle_of(const Chute& chute) { return format_quantity(chute.angle, "deg", 3); }

// The reduced models' deposit label: does the material flow, and does a layer stay?
void judge_deposit(const Chute& chute, const Estimates& es, VerdictBuilder& v) {
  const auto label = label_of(es, "deposit");
  if (!label) return;
  const Estimate* stop = number_of(es, "stopping_thickness");
  const auto outcome = deposit_outcome_from_string(*label);
  if (!outcome)
    v.add(finding(std::nullopt, "deposit", "deposit: " + *label));
  else if (*outcome == DepositOutcome::NeverFlowsBelowTheta1)
    v.add(finding(VerdictStatus::fail, "deposit", "the material never flows at " + angle_of(chute) + " (deposit: " + *label + ")"));
  else if (*outcome == DepositOutcome::NoDepositAboveTheta2)
    v.add(finding(VerdictStatus::pass, "deposit", "no deposit remains at " + angle_of(chute) + " (deposit: " + *label + ")"));
  else
    v.add(finding(VerdictStatus::pass, "deposit",
                  "the material flows down the chute at " + angle_of(chute) + "; a layer " +
                      (stop ? "of " + shown(*stop) + " " : "") + "stays behind",
                  stop));
}

// Each thickness left on the ramp against the allowed one: clear of the band's top is a pass,
// the value within it marginal.
void judge_thickness(const std::string& key, double allowed, const Estimate& e, VerdictBuilder& v) {
  const double value = std::get<double>(e.value);
  const auto status = at_most(value, e.high.value_or(value), allowed);
  const std::string limit = shown(e, allowed);
  std::string text = key == "stopping_thickness" ? "stopping thickness " : "deposit at mid-ramp ";
  text += shown_with_band(e) + " against the allowed " + limit + ": PASS needs " +
          (e.high ? "the band's top" : "the value") + " <= " + limit + (e.high ? ", MARGINAL the value itself" : "");
  if (status == VerdictStatus::marginal) text += ": inside the band";
  v.add(finding(status, key, text, &e, allowed));
}

}  // namespace

Verdict judge_chute(const Chute& chute, const DesignTargets& t, const Estimates& es) {
  VerdictBuilder v;
  judge_deposit(chute, es, v);
  if (t.max_stopping_thickness)
    for (const char* key : {"stopping_thickness", "deposit_thickness_mid_ramp"})
      if (const Estimate* e = number_of(es, key)) judge_thickness(key, *t.max_stopping_thickness, *e, v);
  return v.verdict();
}

}  // namespace feedflow
