#include "designer/design/hopper_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include "designer/design/hopper_assessment.hpp"
#include "designer/design/hopper_charts.hpp"
#include "models/hopper/flow_pattern.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Band {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    low = std::min(low, v);
    high = std::max(high, v);
  }
};

Estimate number(double value, const std::string& unit, const Band& band, std::string model, Rung rung,
                std::string display_unit = "") {
  Estimate e{value, unit, std::nullopt, std::nullopt, std::move(model), rung, std::move(display_unit)};
  if (band.low <= band.high) {
    e.low = std::min(band.low, value);
    e.high = std::max(band.high, value);
  }
  return e;
}

Estimate label(std::string value, std::string model) {
  return Estimate{std::move(value), "", std::nullopt, std::nullopt, std::move(model), Rung::L0, ""};
}

std::string mm(double metres) { return format_quantity(metres, "mm", 3); }
std::string deg(double radians) { return format_quantity(radians, "deg", 3); }

void judge_pattern(const Case& c, const Hopper& h, const FlowPatternVerdict& p, VerdictBuilder& v) {
  const std::string required = c.design.required_flow_pattern;
  const std::string got = to_string(p.pattern);
  const std::string where = "semi-angle " + deg(h.semi_angle) + " against the mass-flow limit " +
                            deg(p.limit.nominal) + " (" + p.limit.model + ")";
  if (required == "any") {
    v.note(got + " flow: " + where);
    return;
  }
  if (got != required) {
    v.fail(required + " flow required, but the hopper gives " + got + " flow: " + where);
    return;
  }
  if (p.pattern == FlowPattern::mass && p.margin < c.design.mass_flow_margin)
    v.marginal("mass flow, but only " + deg(p.margin) + " below the limit (margin " +
               deg(c.design.mass_flow_margin) + " required): " + where);
  else if (p.near_boundary)
    v.marginal(got + " flow, near the boundary: " + p.reason);
  else
    v.pass(got + " flow as required: " + where + ", margin " + deg(std::abs(p.margin)));
}

}  // namespace

void check_hopper(const Case& c, const Hopper& h, const ModelChoices& models, DesignRecord& record,
                  VerdictBuilder& verdict) {
  const HopperMaterial m = HopperMaterial::of(c.material, models);
  const double phi_w = *h.wall_friction_angle;
  const FlowGeometry g = flow_geometry(h);
  const auto variants = material_variants(m, phi_w);

  // Flow pattern, nominal and over the uncertainty of delta and phi_w.
  const FlowPatternVerdict pattern =
      classify_flow_pattern(g, h.semi_angle, m.flow.effective_friction_angle, phi_w);
  Band limit_band;
  for (const auto& var : variants) {
    const auto limit = mass_flow_limit(g, var.effective_friction_angle, var.wall_friction_angle);
    limit_band.add(limit.low);
    limit_band.add(limit.high);
  }

  // Every model at every corner of the uncertainty box.
  std::vector<HopperEvaluation> evaluations;
  for (const auto& var : variants) evaluations.push_back(evaluate_hopper(h, h.semi_angle, h.outlet_width, m, var, models));
  const HopperEvaluation& nominal = evaluations.front();
  Band ff_band, width_band, jenike_band, arch_band, rate_band;
  for (const auto& e : evaluations) {
    ff_band.add(e.flow_factor);
    width_band.add(e.critical_width);
    jenike_band.add(e.jenike.width);
    if (e.static_arch) arch_band.add(e.static_arch->width);
    rate_band.add(e.rate);
  }
  // The rate band also spans the other discharge models at the nominal values.
  for (const char* other : {"johanson", "beverloo", "brown"}) {
    std::vector<std::string> setting{std::string("hopper.discharge=") + other};
    const auto alt = evaluate_hopper(h, h.semi_angle, h.outlet_width, m, variants.front(),
                                     ModelChoices::parse(setting));
    rate_band.add(alt.rate);
  }

  const double length_factor = h.is_wedge() ? *h.slot_length : 1.0;
  const ArchingOutcome outcome = nominal.jenike.outcome;
  const std::string ff_model = models["hopper.flow_factor"] == "rsf"
                                   ? "Jenike radial stress field (shooting)"
                                   : "Enstad/Arnold-McLean closed form";
  auto& results = record.results;
  results.emplace_back("flow_pattern", label(to_string(pattern.pattern), pattern.limit.model));
  results.emplace_back("mass_flow_limit_angle",
                       number(pattern.limit.nominal / kDeg, "deg", Band{limit_band.low / kDeg, limit_band.high / kDeg},
                              pattern.limit.model, Rung::L0));
  results.emplace_back("flow_factor", number(nominal.flow_factor, "", ff_band, ff_model, Rung::L0));
  results.emplace_back("arching", label(outcome == ArchingOutcome::critical_width     ? "cohesive arch below B_c"
                                        : outcome == ArchingOutcome::no_cohesive_arch ? "no cohesive arch"
                                                                                      : "no gravity outlet",
                                        nominal.critical_model));
  if (outcome != ArchingOutcome::no_gravity_outlet) {
    results.emplace_back("critical_outlet_width",
                         number(nominal.critical_width, "m", width_band, nominal.critical_model, Rung::L0, "mm"));
    results.emplace_back("critical_outlet_width_jenike",
                         number(nominal.jenike.width, "m", jenike_band, nominal.jenike.model, Rung::L0, "mm"));
    if (nominal.static_arch)
      results.emplace_back("critical_outlet_width_static_arch",
                           number(nominal.static_arch->width, "m", arch_band, nominal.static_arch->model,
                                  Rung::L0, "mm"));
  }
  std::optional<MechanicalArching> mechanical;
  if (m.largest_size) {
    mechanical = mechanical_arching_width(*m.largest_size);
    results.emplace_back("mechanical_arching_width",
                         number(mechanical->high, "m", Band{mechanical->low, mechanical->high},
                                mechanical->model + " (d_max = d90)", Rung::L0, "mm"));
  }
  if (h.is_wedge())
    results.emplace_back("mass_flow_rate_per_metre",
                         number(nominal.rate, "kg/(s*m)", rate_band, nominal.rate_model, Rung::L0));
  Band total_band{rate_band.low * length_factor, rate_band.high * length_factor};
  const double rate = nominal.rate * length_factor;
  // Hourglass theory neglects wall friction: an upper bound only (plane needs phi > 19.5 deg).
  try {
    const double r1 = h.fill_height / std::cos(h.semi_angle);
    const double bound = hourglass_rate(g, nominal.johanson.bulk_density, h.outlet_width, h.semi_angle,
                                        m.flow.effective_friction_angle, r1) *
                         nominal.drag_factor * length_factor;
    results.emplace_back("mass_flow_rate_upper_bound",
                         number(bound, "kg/s", Band{}, "hourglass theory (no wall friction): an upper bound", Rung::L0));
  } catch (const std::invalid_argument&) {
    verdict.note("the hourglass upper bound does not apply (internal friction too low)");
  }
  results.emplace_back("mass_flow_rate", number(nominal.rate * length_factor, "kg/s", total_band,
                                                nominal.rate_model + (h.is_wedge() ? " x slot length" : ""),
                                                Rung::L0));
  // Emptying at the steady rate (the rate does not depend on the head, Beverloo/Johanson).
  const double content = c.material.bulk.density * h.filled_volume();
  const double loose = c.material.bulk.loose_density.value_or(c.material.bulk.density) * h.filled_volume();
  results.emplace_back("hopper_content", number(content, "kg", Band{loose, content},
                                                "filled volume x bulk density (loose .. design)", Rung::L0));
  if (rate > 0.0)
    results.emplace_back("discharge_time",
                         number(content / rate, "s", Band{content / total_band.high, content / total_band.low},
                                "hopper content / mass flow rate (steady discharge)", Rung::L0));
  record.charts = hopper_charts(h, m, models, nominal, pattern);
  if (rate > 0.0) {
    Chart emptying{"discharged_mass_vs_time", "Discharged mass against time", {"time", "s"},
                   {"discharged mass", "kg"}, {}, ""};
    for (const auto& [label, q, style] : {std::tuple{"steady discharge", rate, SeriesStyle::line},
                                          std::tuple{"band, low rate", total_band.low, SeriesStyle::dashed},
                                          std::tuple{"band, high rate", total_band.high, SeriesStyle::dashed}}) {
      const double empty_at = content / q;
      emptying.series.push_back({label, style, {0.0, empty_at, std::max(1.2 * content / total_band.low, empty_at)},
                                 {0.0, content, content}, {}});
    }
    emptying.note = "Reduced model: a constant rate until the hopper is empty; a simulation shows the start-up and "
                    "the end of discharge.";
    record.charts.push_back(std::move(emptying));
  }

  // Verdict.
  judge_pattern(c, h, pattern, verdict);
  verdict.note("arching: " + nominal.jenike.statement);
  const double sf = c.design.outlet_safety_factor;
  const double w = h.outlet_width;
  if (outcome == ArchingOutcome::no_gravity_outlet) {
    verdict.fail("no gravity outlet prevents cohesive arching (" + nominal.jenike.statement + "): flow aids needed");
  } else if (outcome == ArchingOutcome::no_cohesive_arch) {
    verdict.pass("no cohesive arch forms (the flow function lies below the flow-factor line)");
  } else {
    const double need = sf * nominal.critical_width, need_high = sf * width_band.high;
    const std::string text = "outlet " + mm(w) + " against " + format_number(sf, 3) + " x B_c = " + mm(need) +
                             " (B_c band " + mm(width_band.low) + " .. " + mm(width_band.high) + ")";
    // The outlet is exact; the requirement has a band: clear of its top is a pass.
    const auto status = w >= need_high ? VerdictStatus::pass
                        : w >= need    ? VerdictStatus::marginal
                                       : VerdictStatus::fail;
    verdict.add(status, status == VerdictStatus::pass       ? text + ": clear of arching"
                        : status == VerdictStatus::marginal ? text + ": inside the uncertainty band"
                                                            : text + ": the outlet arches");
  }
  if (mechanical) {
    if (w < mechanical->low)
      verdict.fail("outlet " + mm(w) + " is under 3 d_max (" + mm(mechanical->low) + "): particles interlock");
    else if (w < mechanical->high)
      verdict.marginal("outlet " + mm(w) + " is within 3-8 d_max (" + mm(mechanical->low) + " .. " +
                       mm(mechanical->high) + "): interlocking arches are possible");
  }
  if (c.design.required_throughput) {
    const double req = *c.design.required_throughput;
    const auto status = verdict.judge_at_least(rate, total_band.low, req);
    verdict.add(status, "discharge " + format_quantity(rate, "kg/s", 3) + " (band " +
                            format_quantity(total_band.low, "kg/s", 3) + " .. " +
                            format_quantity(total_band.high, "kg/s", 3) + ") against the required " +
                            format_quantity(req, "kg/s", 3));
  }

  // What the models assume, and which way each number errs.
  auto& a = record.assumptions;
  a.push_back("Critical outlet width: " + nominal.critical_model +
              ". Jenike's method is known to overpredict B_c (errs wide, the safe side); the static-arch "
              "estimate H_a is derived, not a published formula, and falls on steep smooth walls.");
  a.push_back("Bulk density: " + m.density_model + ".");
  if (h.is_wedge())
    a.push_back("Wedge: plane flow assumes a slot at least 3 outlet widths long; the mass-flow limit uses the "
                "interim rule 'conical limit + 8-12 deg' (no verified closed form for plane flow).");
  a.push_back("Continuum arching theory does not model interlocking of particles; the (3-8) d_max rule covers it "
              "roughly.");
  a.push_back("Discharge: " + nominal.rate_model + "; expect +-20-30 % before calibration; Beverloo tends to "
              "overpredict for elongated particles.");
  if (nominal.drag_factor < 1.0)
    a.push_back("Air drag (Carleton) lowers the rate to " + format_number(nominal.drag_factor * 100, 3) +
                " % of the drag-free value with d = d50; finer fractions would lower it further.");
  for (const auto& [key, source] : c.material.sources)
    if ((key.rfind("flow_properties.", 0) == 0) && source.find("assumed") != std::string::npos) {
      a.push_back("The flow function and effective friction angle of " + c.material.name +
                  " are assumed calibration targets, not measurements: measure the flow function below 1 kPa "
                  "before building (a 0.1 kPa error moves B_c by about 40 mm).");
      break;
    }
}

}  // namespace feedflow
