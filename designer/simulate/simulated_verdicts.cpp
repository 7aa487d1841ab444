#include "designer/simulate/simulated_verdicts.hpp"

#include "designer/design/verdict_builder.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

const std::string* label_of(const DesignRecord& r, const std::string& key) {
  const Estimate* e = find_result(r, key);
  return e && !e->is_number() ? &std::get<std::string>(e->value) : nullptr;
}

Verdict finish(const VerdictBuilder& v) {
  Verdict out = v.verdict();
  if (!v.judged()) out.status = VerdictStatus::unknown;
  return out;
}

}  // namespace

Verdict judge_simulated_hopper(const Case& c, const DesignRecord& r) {
  VerdictBuilder v;
  const std::string* arching = label_of(r, "arching");
  const bool arched = arching && *arching == "arched";
  if (arched) v.fail("the simulated discharge arches over the outlet");
  const Estimate* q = find_result(r, "mass_flow_rate");
  if (!arched && q && q->is_number()) {
    const double rate = std::get<double>(q->value), low = q->low.value_or(rate), high = q->high.value_or(rate);
    const std::string text = "simulated discharge " + format_quantity(rate, "kg/s", 3) + " (band " +
                             format_quantity(low, "kg/s", 3) + " .. " + format_quantity(high, "kg/s", 3) + ")";
    if (c.design.required_throughput) {
      const double required = *c.design.required_throughput;
      v.add(v.judge_at_least(rate, low, required), text + " against the required " + format_quantity(required, "kg/s", 3));
    } else {
      v.pass(text + ": the hopper discharges steadily");
    }
  }
  const std::string* pattern = label_of(r, "flow_pattern");
  const std::string& required = c.design.required_flow_pattern;
  if (!arched && pattern && required != "any") {
    if (*pattern == required) v.pass(*pattern + " flow, as required");
    else v.fail(required + " flow required, the simulation shows " + *pattern + " flow");
  }
  return finish(v);
}

Verdict judge_simulated_chute(const Case& c, const DesignRecord& r) {
  VerdictBuilder v;
  const Estimate* h = find_result(r, "deposit_thickness_mid_ramp");
  if (h && h->is_number() && c.design.max_stopping_thickness) {
    const double value = std::get<double>(h->value), high = h->high.value_or(value);
    const double limit = *c.design.max_stopping_thickness;
    v.add(v.judge_at_least(limit - value, limit - high, 0.0),
          "simulated deposit at mid-ramp " + format_quantity(value, "mm", 3) + " (band up to " +
              format_quantity(high, "mm", 3) + ") against the allowed " + format_quantity(limit, "mm", 3));
  } else if (h && h->is_number()) {
    v.note("simulated deposit at mid-ramp " + format_quantity(std::get<double>(h->value), "mm", 3));
  }
  return finish(v);
}

Verdict judge_simulated_drum(const Case& c, const DesignRecord& r) {
  VerdictBuilder v;
  const std::string* regime = label_of(r, "regime");
  const std::string& required = c.design.required_regime;
  if (regime && *regime != "not measured" && !required.empty() && required != "any") {
    if (*regime == required) v.pass("the simulated bed is " + required + " as required");
    else v.fail("the simulated bed is " + *regime + ", " + required + " is required");
  }
  return finish(v);
}

}  // namespace feedflow
