// The chute's judge (judge.hpp): whether the material flows and what stays on the ramp, from the
// estimates present.
#include <limits>
#include <optional>

#include "designer/design/estimate_reading.hpp"
#include "designer/design/judge.hpp"
#include "designer/design/verdict_builder.hpp"
#include "models/chute/pouliquen_law.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::string angle_of(const Chute& chute) { return format_quantity(chute.angle, "deg", 3); }

// The outcome of a corner of the law's uncertainty that disagrees with the nominal deposit (it
// never flows while the nominal law leaves a layer, or the other way round), when one does.
std::optional<DepositOutcome> edge_of(const Estimates& es) {
  const auto edge = label_of(es, "deposit_within_uncertainty");
  return edge ? deposit_outcome_from_string(*edge) : std::nullopt;
}
bool may_not_flow(const Estimates& es) {
  return edge_of(es) == DepositOutcome::NeverFlowsBelowTheta1;
}

// The reduced models' deposit label: does the material flow, and does a layer stay?
void judge_deposit(const Chute& chute, const Estimates& es, VerdictBuilder& v) {
  const auto label = label_of(es, "deposit");
  if (!label) return;
  const Estimate* stop = number_of(es, "stopping_thickness");
  const auto outcome = deposit_outcome_from_string(*label);
  // Whether the material flows at all differs across the law's uncertainty: MARGINAL.
  const bool edge_differs = edge_of(es).has_value();
  const std::string edge = edge_differs
                               ? ", but within the law's uncertainty it " +
                                     std::string(may_not_flow(es) ? "may never flow" : "may flow")
                               : std::string();
  const VerdictStatus status = edge_differs ? VerdictStatus::marginal : VerdictStatus::pass;
  if (!outcome)
    v.add(finding(std::nullopt, "deposit", "deposit: " + *label));
  else if (*outcome == DepositOutcome::NeverFlowsBelowTheta1) {
    // A release still spreads and stops: say what it leaves.
    const Estimate* release = number_of(es, "deposit_thickness_mid_ramp");
    v.add(finding(edge_differs ? VerdictStatus::marginal : VerdictStatus::fail, "deposit",
                  "the material does not flow steadily at " + angle_of(chute) +
                      " (deposit: " + *label + ")" + edge +
                      (release ? "; a release from the bin runs out and comes to rest, " +
                                     shown(*release) + " thick at mid-ramp"
                               : std::string())));
  } else if (*outcome == DepositOutcome::NoDepositAboveTheta2)
    v.add(
        finding(status, "deposit",
                "no deposit remains at " + angle_of(chute) + " (deposit: " + *label + ")" + edge));
  else
    v.add(finding(status, "deposit",
                  "the material flows down the chute at " + angle_of(chute) + "; a layer " +
                      (stop ? "of " + shown(*stop) + " " : "") + "stays behind" + edge,
                  stop));
}

// Each thickness left on the ramp against the allowed one: clear of the band's top is a pass,
// the value within it marginal. `unbounded`: the band has no top (the material may never flow),
// so a value within the limit is marginal at best.
void judge_thickness(const std::string& key, double allowed, const Estimate& e, bool unbounded,
                     VerdictBuilder& v) {
  const double value = std::get<double>(e.value);
  const double top = unbounded ? std::numeric_limits<double>::infinity() : e.high.value_or(value);
  const auto status = at_most(value, top, allowed);
  const std::string limit = shown(e, allowed);
  std::string text = key == "stopping_thickness" ? "stopping thickness " : "deposit at mid-ramp ";
  text += shown_with_band(e) + " against the allowed " + limit + ": PASS needs " +
          (e.high ? "the band's top" : "the value") + " <= " + limit + (e.high ? ", MARGINAL the value itself" : "");
  if (status == VerdictStatus::marginal)
    text += unbounded ? ": the band has no top (the material may never flow)" : ": inside the band";
  v.add(finding(status, key, text, &e, allowed));
}

}  // namespace

Verdict judge_chute(const Chute& chute, const DesignTargets& t, const Estimates& es) {
  VerdictBuilder v;
  judge_deposit(chute, es, v);
  if (t.max_stopping_thickness)
    for (const char* key : {"stopping_thickness", "deposit_thickness_mid_ramp"})
      if (const Estimate* e = number_of(es, key))
        judge_thickness(key, *t.max_stopping_thickness, *e, may_not_flow(es), v);
  return v.verdict();
}

}  // namespace feedflow
