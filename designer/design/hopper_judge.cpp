// The hopper's judge (judge.hpp): flow pattern, arching at the outlet, interlocking and
// throughput, from the estimates present.
#include <cmath>
#include <numbers>

#include "designer/design/estimate_reading.hpp"
#include "designer/design/judge.hpp"
#include "designer/design/verdict_builder.hpp"
#include "models/hopper/critical_outlet.hpp"
#include "models/hopper/flow_pattern.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::string mm(double metres) { return format_quantity(metres, "mm", 3); }
std::string deg(double radians) { return format_quantity(radians, "deg", 3); }

// What an `arching` label of any rung says of the outlet: the reduced models' outcomes and the
// simulations' observations, one rule for all. `status` empty: the label does not decide, the
// critical outlet width does.
struct ArchingLabel {
  std::string_view label;
  std::optional<VerdictStatus> status;
  std::string_view says;
  bool width_applies;  // a critical outlet width, when present, is judged too
};
const ArchingLabel kArchingLabels[] = {
    {"arched", VerdictStatus::fail, "the outlet arches (observed)", true},
    {arching_label(ArchingOutcome::no_gravity_outlet), VerdictStatus::fail,
     "no gravity outlet prevents cohesive arching: flow aids needed", false},
    {"flowing", VerdictStatus::pass, "the outlet flows (observed)", true},
    {"flows", VerdictStatus::pass, "the outlet flows (observed)", true},
    {"emptied (no arch)", VerdictStatus::pass, "the hopper emptied without arching (observed)", true},
    {arching_label(ArchingOutcome::no_cohesive_arch), VerdictStatus::pass,
     "no cohesive arch forms (the flow function lies below the flow-factor line)", false},
    {arching_label(ArchingOutcome::critical_width), std::nullopt, "", true},
};

// The flow pattern against the required one; not judged when the outlet arched (nothing flowed).
void judge_pattern(const Hopper& h, const DesignTargets& t, const Estimates& es, bool arched, VerdictBuilder& v) {
  const auto got = label_of(es, "flow_pattern");
  if (!got) return;
  if ((*got != to_string(FlowPattern::mass) && *got != to_string(FlowPattern::funnel)) || arched) {
    v.add(finding(std::nullopt, "flow_pattern", "flow pattern " + *got + ": not judged" +
                                                    (arched ? " (the outlet arched)" : "")));
    return;
  }
  const Estimate* limit = number_of(es, "mass_flow_limit_angle");
  const Estimate* margin = number_of(es, "flow_pattern_margin");
  const std::string where = limit ? ": semi-angle " + deg(h.semi_angle) + " against the mass-flow limit " +
                                        shown(*limit) + " (" + limit->model + ")"
                                  : "";
  const std::string& required = t.required_flow_pattern;
  if (required == "any") {
    v.add(finding(std::nullopt, "flow_pattern", *got + " flow" + where, margin));
  } else if (*got != required) {
    v.add(finding(VerdictStatus::fail, "flow_pattern",
                  required + " flow required, but the hopper gives " + *got + " flow" + where, margin,
                  margin ? std::optional<double>(0.0) : std::nullopt));
  } else if (*got == to_string(FlowPattern::mass) && margin && std::get<double>(margin->value) * kDegree < t.mass_flow_margin) {
    v.add(finding(VerdictStatus::marginal, "flow_pattern_margin",
                  "mass flow, but only " + shown(*margin) + " below the limit (margin " + deg(t.mass_flow_margin) +
                      " required)" + where,
                  margin, t.mass_flow_margin / kDegree));
  } else if (const Estimate* near = find_estimate(es, "flow_pattern_boundary");
             near && label_of(es, "flow_pattern_boundary") == kNearBoundary) {
    v.add(finding(VerdictStatus::marginal, "flow_pattern_boundary", *got + " flow, near the boundary: " + near->model,
                  margin));
  } else {
    const std::string by = margin ? ", margin " + shown(*margin, std::abs(std::get<double>(margin->value))) : "";
    // The margin held against the required one in mass flow, against the boundary in funnel flow.
    const double held = *got == to_string(FlowPattern::mass) ? t.mass_flow_margin / kDegree : 0.0;
    v.add(finding(VerdictStatus::pass, "flow_pattern", *got + " flow as required" + where + by, margin,
                  margin ? std::optional<double>(held) : std::nullopt));
  }
}

// The outlet against the critical width with the safety factor. The outlet is exact, B_c has a
// band: clear of the band's top is a pass, between B_c and the top marginal.
void judge_critical_width(const Hopper& h, const DesignTargets& t, const Estimate& bc, VerdictBuilder& v) {
  const double sf = t.outlet_safety_factor, w = h.outlet_width;
  const double value = std::get<double>(bc.value), top = bc.high.value_or(value);
  const std::string times = format_number(sf, 3) + " x B_c";
  const std::string rule = "outlet " + mm(w) + ": PASS needs outlet >= " + times +
                           (bc.high ? " band top = " + mm(sf * top) + ", MARGINAL from " + times : "") + " = " +
                           mm(sf * value) + " (B_c " + shown(bc) + (bc.high ? ", band " + band_of(bc) : "") + ")";
  const auto status = w >= sf * top ? VerdictStatus::pass : w >= sf * value ? VerdictStatus::marginal : VerdictStatus::fail;
  v.add(finding(status, "critical_outlet_width",
                rule + (status == VerdictStatus::pass       ? ": clear of arching"
                        : status == VerdictStatus::marginal ? ": inside the uncertainty band"
                                                            : ": the outlet arches"),
                &bc, w / sf));
}

// The row of kArchingLabels for the estimates' arching label; null without one or for a label
// the table does not know.
const ArchingLabel* arching_label(const Estimates& es) {
  const auto label = label_of(es, "arching");
  for (const auto& l : kArchingLabels)
    if (label && l.label == *label) return &l;
  return nullptr;
}

// Arching at the outlet: the arching label, then B_c where it applies.
void judge_arching(const Hopper& h, const DesignTargets& t, const Estimates& es, VerdictBuilder& v) {
  const ArchingLabel* call = arching_label(es);
  if (const auto label = label_of(es, "arching"); label && !call)
    v.add(finding(std::nullopt, "arching", "arching: " + *label));
  if (call && call->status) v.add(finding(call->status, "arching", std::string(call->says)));
  if (const Estimate* bc = number_of(es, "critical_outlet_width"); bc && (!call || call->width_applies))
    judge_critical_width(h, t, *bc, v);
}

// Interlocking of particles: (3-8) d_max, a band without a decisive value.
void judge_interlocking(const Hopper& h, const Estimate& range, VerdictBuilder& v) {
  const double w = h.outlet_width, value = std::get<double>(range.value);
  const double low = range.low.value_or(value), high = range.high.value_or(value);
  const auto status = w >= high ? VerdictStatus::pass : w >= low ? VerdictStatus::marginal : VerdictStatus::fail;
  const std::string rule = "outlet " + mm(w) + " against the interlocking range " + shown(range, low) + " .. " +
                           shown(range, high) + ": PASS needs outlet >= " + shown(range, high) + ", MARGINAL from " +
                           shown(range, low);
  v.add(finding(status, "mechanical_arching_width",
                rule + (status == VerdictStatus::pass       ? ": clear of interlocking"
                        : status == VerdictStatus::marginal ? ": interlocking arches are possible"
                                                            : ": particles interlock"),
                &range, w));
}

void judge_throughput(double required, const Estimate& q, VerdictBuilder& v) {
  const double value = std::get<double>(q.value);
  const auto status = at_least(value, q.low.value_or(value), required);
  const std::string req = shown(q, required);
  v.add(finding(status, "mass_flow_rate",
                "discharge " + shown_with_band(q) + " against the required " + req + ": PASS needs " +
                    (q.low ? "the band's low end" : "the rate") + " >= " + req +
                    (q.low ? ", MARGINAL the value itself" : ""),
                &q, required));
}

}  // namespace

Verdict judge_hopper(const Hopper& h, const DesignTargets& t, const Estimates& es) {
  VerdictBuilder v;
  const ArchingLabel* arching = arching_label(es);
  judge_pattern(h, t, es, arching && arching->label == "arched", v);
  judge_arching(h, t, es, v);
  if (const Estimate* range = number_of(es, "mechanical_arching_width")) judge_interlocking(h, *range, v);
  if (const Estimate* q = number_of(es, "mass_flow_rate"); q && t.required_throughput)
    judge_throughput(*t.required_throughput, *q, v);
  return v.verdict();
}

}  // namespace feedflow
