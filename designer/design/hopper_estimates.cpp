#include "designer/design/hopper_estimates.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/hopper/discharge_rate.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

// Flow pattern, its limit and margin over the box; the flow factor.
void pattern_results(const Hopper& h, const HopperAssessment& a, Estimates& results) {
  const FlowPatternVerdict& p = a.pattern;
  results.emplace_back("flow_pattern", labelled(to_string(p.pattern), p.limit.model));
  results.emplace_back("mass_flow_limit_angle", banded(p.limit.nominal / kDegree, "deg", Band{a.limit.low / kDegree, a.limit.high / kDegree},
                                                       p.limit.model, Rung::L0));
  const Band margin{(a.limit.low - h.semi_angle) / kDegree, (a.limit.high - h.semi_angle) / kDegree};
  results.emplace_back("flow_pattern_margin",
                       banded(p.margin / kDegree, "deg", margin,
                              "mass-flow limit angle - semi-angle (negative in funnel flow)", Rung::L0));
  results.emplace_back("flow_pattern_boundary",
                       labelled(p.near_boundary ? kNearBoundary : kClearOfBoundary, p.reason));
  results.emplace_back("flow_factor", banded(a.nominal().flow_factor, "", a.flow_factor,
                                             std::string(a.models.flow_factor->summary), a.models.flow_factor->rung));
}

// Cohesive arching (B_c by the chosen model and each estimate) and interlocking.
void arching_results(const HopperAssessment& a, Estimates& results) {
  const HopperEvaluation& nominal = a.nominal();
  const ArchingOutcome outcome = nominal.jenike.outcome;
  results.emplace_back("arching", labelled(arching_label(outcome), nominal.critical_model));
  if (outcome != ArchingOutcome::no_gravity_outlet) {
    results.emplace_back("critical_outlet_width",
                         banded(nominal.critical_width, "m", a.width, nominal.critical_model, Rung::L0, "mm"));
    results.emplace_back("critical_outlet_width_jenike",
                         banded(nominal.jenike.width, "m", a.jenike, nominal.jenike.model, Rung::L0, "mm"));
    if (nominal.static_arch)
      results.emplace_back("critical_outlet_width_static_arch", banded(nominal.static_arch->width, "m", a.static_arch,
                                                                       nominal.static_arch->model, Rung::L0, "mm"));
  }
  if (a.mechanical)
    results.emplace_back("mechanical_arching_width",
                         banded(a.mechanical->high, "m", Band{a.mechanical->low, a.mechanical->high},
                                a.mechanical->model + " (d_max = d90)", Rung::L0, "mm"));
}

// Discharge: the rate with its band, the hourglass bound, the content and the emptying time.
void discharge_results(const Material& material, const Hopper& h, const HopperAssessment& a, HopperEstimates& out) {
  auto& results = out.results;
  const HopperEvaluation& nominal = a.nominal();
  const double length = h.is_wedge() ? *h.slot_length : 1.0;
  if (h.is_wedge())
    results.emplace_back("mass_flow_rate_per_metre", banded(nominal.rate, "kg/(s*m)", a.rate, nominal.rate_model, Rung::L0));
  const Band total = a.rate.scaled(length);
  const double rate = nominal.rate * length;
  // Hourglass theory neglects wall friction: an upper bound only (plane needs phi > 19.5 deg).
  try {
    const double r1 = h.fill_height / std::cos(h.semi_angle);
    const double bound = hourglass_rate(flow_geometry(h), nominal.johanson.bulk_density, h.outlet_width, h.semi_angle,
                                        a.material.flow.effective_friction_angle, r1) *
                         nominal.drag_factor * length;
    results.emplace_back("mass_flow_rate_upper_bound",
                         banded(bound, "kg/s", Band{}, "hourglass theory (no wall friction): an upper bound", Rung::L0));
  } catch (const std::invalid_argument&) {
    out.notes.push_back({std::nullopt, "mass_flow_rate_upper_bound",
                         "the hourglass upper bound does not apply (internal friction too low)"});
  }
  results.emplace_back("mass_flow_rate", banded(rate, "kg/s", total,
                                                nominal.rate_model + (h.is_wedge() ? " x slot length" : ""), Rung::L0));
  // Emptying at the steady rate (the rate does not depend on the head, Beverloo/Johanson).
  const double content = material.bulk.density * h.filled_volume();
  const double loose = material.bulk.loose_density.value_or(material.bulk.density) * h.filled_volume();
  results.emplace_back("hopper_content", banded(content, "kg", Band{loose, content},
                                                "filled volume x bulk density (loose .. design)", Rung::L0));
  // A rate band reaching zero (an outlet that may arch) leaves the time without an upper end.
  if (rate > 0.0 && total.low > 0.0)
    results.emplace_back("discharge_time", banded(content / rate, "s", Band{content / total.high, content / total.low},
                                                  "hopper content / mass flow rate (steady discharge)", Rung::L0));
  else if (rate > 0.0)
    results.emplace_back("discharge_time",
                         banded(content / rate, "s", Band{},
                                "hopper content / mass flow rate (steady discharge); no band: the rate's band "
                                "reaches zero (the outlet may arch), so the time has no upper end",
                                Rung::L0));
}

}  // namespace

HopperAssessment assess_hopper(const Hopper& h, HopperMaterial m, const HopperModels& models) {
  const double phi_w = *h.wall_friction_angle;
  const FlowGeometry g = flow_geometry(h);
  const auto variants = material_variants(m, phi_w);
  FlowPatternVerdict pattern = classify_flow_pattern(g, h.semi_angle, m.flow.effective_friction_angle, phi_w);
  HopperAssessment a{std::move(m), models, std::move(pattern), {}, {}, {}, {}, {}, {}, {}, std::nullopt};
  for (const auto& var : variants) {
    const auto limit = mass_flow_limit(g, var.effective_friction_angle, var.wall_friction_angle);
    a.limit.add(limit.low);
    a.limit.add(limit.high);
    const HopperEvaluation& e =
        a.evaluations.emplace_back(evaluate_hopper(h, h.semi_angle, h.outlet_width, a.material, var, models));
    a.flow_factor.add(e.flow_factor);
    a.width.add(e.critical_width);
    a.jenike.add(e.jenike.width);
    if (e.static_arch) a.static_arch.add(e.static_arch->width);
    a.rate.add(e.rate);
  }
  // The rate band also spans the other discharge models at the nominal values.
  for (const DischargeModel& row : discharge_models().rows) {
    if (!row.spans_band) continue;
    HopperModels alternative = models;  // the chosen flow factor and critical outlet
    alternative.discharge = &row;
    a.rate.add(evaluate_hopper(h, h.semi_angle, h.outlet_width, a.material, variants.front(), alternative).rate);
  }
  // A calibrated row errs against the full rung by its measured error: the band spans that too.
  if (const auto error = calibrated_error(*models.discharge, g, a.material.discharge_calibration);
      error && !a.rate.empty()) {
    const Band spanned = a.rate;
    a.rate.add(spanned.low * (1.0 - *error));
    a.rate.add(spanned.high * (1.0 + *error));
  }
  if (a.material.largest_size) a.mechanical = mechanical_arching_width(*a.material.largest_size);
  return a;
}

HopperEstimates hopper_estimates(const Material& material, const Hopper& h, const HopperAssessment& a) {
  HopperEstimates out;
  pattern_results(h, a, out.results);
  arching_results(a, out.results);
  out.notes.push_back({std::nullopt, "arching", "arching: " + a.nominal().jenike.statement()});
  discharge_results(material, h, a, out);
  return out;
}

}  // namespace feedflow
