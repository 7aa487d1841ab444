#include "designer/design/hopper_charts.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "models/hopper/bin_stresses.hpp"
#include "models/hopper/hopper_slice_stresses.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::vector<double> range(double from, double to, int points) {
  std::vector<double> v;
  for (int i = 0; i < points; ++i) v.push_back(from + (to - from) * i / (points - 1));
  return v;
}

Chart outlet_against_angle(const Hopper& h, const HopperMaterial& m, const HopperModels& models,
                           const FlowPatternVerdict& pattern) {
  Chart c{"critical_outlet_width_vs_semi_angle", "Critical outlet width against semi-angle",
          {"semi-angle", "deg"}, {"critical outlet width", "mm"}, {}, ""};
  const double top = std::min(60.0 * kDegree, std::max(h.semi_angle, pattern.limit.high) + 5.0 * kDegree);
  const auto angles = range(5.0 * kDegree, top, 23);
  const auto corners = material_variants(m, *h.wall_friction_angle, true);
  const auto nominal_variant = material_variants(m, *h.wall_friction_angle).front();
  // One band per model over the corners of the material's uncertainty.
  ChartSeries jenike_band{"Jenike band", SeriesStyle::band, {}, {}, {}, 0};
  ChartSeries arch_band{"static-arch band", SeriesStyle::band, {}, {}, {}, 1};
  ChartSeries jenike{"Jenike H(theta)", SeriesStyle::line, {}, {}, {}, 0};
  ChartSeries arch{"static arch H_a", SeriesStyle::dashed, {}, {}, {}, 1};
  const auto mm_or_gap = [](double w) { return std::isfinite(w) ? w * 1e3 : NAN; };
  for (double theta : angles) {
    const double x = theta / kDegree;
    const auto e = evaluate_hopper(h, theta, h.outlet_width, m, nominal_variant, models);
    double j_lo = e.jenike.width, j_hi = e.jenike.width;
    double a_lo = e.static_arch ? e.static_arch->width : NAN, a_hi = a_lo;
    for (const auto& v : corners) {
      const auto corner = evaluate_hopper(h, theta, h.outlet_width, m, v, models);
      j_lo = std::min(j_lo, corner.jenike.width);
      j_hi = std::max(j_hi, corner.jenike.width);
      if (corner.static_arch) {
        a_lo = std::min(a_lo, corner.static_arch->width);
        a_hi = std::max(a_hi, corner.static_arch->width);
      }
    }
    jenike_band.x.push_back(x);
    jenike_band.y.push_back(mm_or_gap(j_lo));
    jenike_band.y_upper.push_back(mm_or_gap(j_hi));
    jenike.x.push_back(x);
    jenike.y.push_back(mm_or_gap(e.jenike.width));
    if (e.static_arch) {
      arch_band.x.push_back(x);
      arch_band.y.push_back(mm_or_gap(a_lo));
      arch_band.y_upper.push_back(mm_or_gap(a_hi));
      arch.x.push_back(x);
      arch.y.push_back(mm_or_gap(e.static_arch->width));
    }
  }
  c.series = {jenike_band};
  if (!arch.x.empty()) c.series.push_back(arch_band);
  c.series.push_back(jenike);
  if (!arch.x.empty()) c.series.push_back(arch);
  std::vector<double> uppers = jenike_band.y_upper;
  uppers.insert(uppers.end(), arch_band.y_upper.begin(), arch_band.y_upper.end());
  double tallest = h.outlet_width * 1e3;
  for (double y : uppers)
    if (std::isfinite(y)) tallest = std::max(tallest, y);
  c.series.push_back({"mass-flow limit", SeriesStyle::dashed,
                      {pattern.limit.nominal / kDegree, pattern.limit.nominal / kDegree}, {0.0, tallest}, {}, 2});
  c.series.push_back({"design outlet", SeriesStyle::marker, {h.semi_angle / kDegree}, {h.outlet_width * 1e3}, {}, 6});
  c.note = "Each model's band spans the material's uncertainty (delta, wall friction, flow function). The "
           "design outlet must sit above the bands with the safety factor; Jenike errs wide (safe side).";
  return c;
}

// Jenike's flow-function chart: the strength the material gains under consolidation against the
// strength an arch's own stress can break (the flow-factor line sigma1/ff); they cross at the
// critical point that sizes B_c.
Chart flow_function_chart(const HopperMaterial& m, const HopperAssessment& a) {
  Chart c{"flow_function",
          "Flow function and flow-factor line (Jenike)",
          {"major consolidation stress", "kPa"},
          {"unconfined yield strength", "kPa"},
          {},
          ""};
  const HopperEvaluation& nominal = a.nominal();
  const bool crossing = nominal.jenike.outcome == ArchingOutcome::critical_width;
  const FlowFunction nominal_ff = scaled_flow_function(m.flow, 1.0);
  // Three times the critical stress, so the crossing sits in the chart's first third.
  const double top = crossing ? 3.0 * nominal.jenike.major_stress : 5e3;
  const bool pascal = top < 2e3;  // a weak arch's stresses read better in Pa
  const double unit = pascal ? 1.0 : 1e3;
  c.x.unit = c.y.unit = pascal ? "Pa" : "kPa";
  // sigma_c at -, + its uncertainty, as the material's uncertainty box has it.
  const FlowFunction low = scaled_flow_function(m.flow, 1.0 - m.flow.ff_uncertainty),
                     high = scaled_flow_function(m.flow, 1.0 + m.flow.ff_uncertainty);
  ChartSeries band{"flow function band (strength uncertainty)", SeriesStyle::band, {}, {}, {}, 0};
  ChartSeries curve{"flow function " + nominal_ff.describe(), SeriesStyle::line, {}, {}, {}, 0};
  ChartSeries ff_band{"flow-factor lines over the uncertainty", SeriesStyle::band, {}, {}, {}, 1};
  ChartSeries ff{"flow-factor line sigma1/ff, ff = " + format_number(nominal.flow_factor, 3),
                 SeriesStyle::dashed,
                 {},
                 {},
                 {},
                 1};
  for (double s1 : range(0.0, top, 41)) {
    const double x = s1 / unit;
    band.x.push_back(x);
    band.y.push_back(low.unconfined_yield_strength(s1) / unit);
    band.y_upper.push_back(high.unconfined_yield_strength(s1) / unit);
    curve.x.push_back(x);
    curve.y.push_back(nominal_ff.unconfined_yield_strength(s1) / unit);
    ff_band.x.push_back(x);
    ff_band.y.push_back(x / a.flow_factor.high);
    ff_band.y_upper.push_back(x / a.flow_factor.low);
    ff.x.push_back(x);
    ff.y.push_back(x / nominal.flow_factor);
  }
  c.series = {band, ff_band, curve, ff};
  if (crossing)
    c.series.push_back({"critical point",
                        SeriesStyle::marker,
                        {nominal.jenike.major_stress / unit},
                        {nominal.jenike.critical_strength / unit},
                        {},
                        6});
  c.note =
      crossing
          ? "An arch holds where the flow function lies above the flow-factor line; they cross at "
            "sigma1* = " +
                format_quantity(nominal.jenike.major_stress, c.x.unit, 3) + ", sigma_c,crit = " +
                format_quantity(nominal.jenike.critical_strength, c.y.unit, 3) +
                ", which sizes B_c = H(theta) sigma_c,crit / (rho_b g)."
          : std::string("The curves do not cross (") + arching_label(nominal.jenike.outcome) + ").";
  return c;
}

Chart rate_against_outlet(const Hopper& h, const HopperMaterial& m, const HopperModels& models,
                          const HopperEvaluation& nominal) {
  const bool wedge = h.is_wedge();
  const double length = wedge ? *h.slot_length : 1.0;
  Chart c{"mass_flow_rate_vs_outlet_width", "Discharge rate against outlet width", {"outlet width", "mm"},
          {wedge ? "mass flow rate (slot)" : "mass flow rate", "kg/s"}, {}, ""};
  // From the critical width (or where the correlations hold, B >= 6 d50) to well past the design.
  const double arching = std::isfinite(nominal.critical_width) ? nominal.critical_width : 0.0;
  const double from = std::max({arching, 6.0 * m.median_size.value_or(0.0), 0.2 * h.outlet_width});
  const double to = std::max(2.5 * h.outlet_width, 2 * from);
  const auto widths = range(from, to, 25);
  const auto nominal_variant = material_variants(m, *h.wall_friction_angle).front();
  const auto& rows = discharge_models().rows;
  for (const DischargeModel& row : rows) {
    HopperModels choice = models;  // the chosen flow factor, this discharge model
    choice.discharge = &row;
    ChartSeries s{std::string(row.legend), &row == &rows.front() ? SeriesStyle::line : SeriesStyle::dashed, {}, {}, {}};
    for (double w : widths) {
      const HopperEvaluation e = evaluate_hopper(h, h.semi_angle, w, m, nominal_variant, choice);
      if (e.rate_row != &row) break;  // the model does not apply to this hopper
      s.x.push_back(w * 1e3);
      s.y.push_back(e.rate * length);
    }
    if (!s.x.empty()) c.series.push_back(std::move(s));
  }
  c.series.push_back({"design outlet", SeriesStyle::marker, {h.outlet_width * 1e3}, {nominal.rate * length}, {}, 6});
  c.note = "Johanson goes to zero at the critical outlet width; the spread between the correlations is part of "
           "the rate's band.";
  return c;
}

Chart pattern_chart(const Hopper& h, const HopperMaterial& m, const FlowPatternVerdict& pattern) {
  const FlowGeometry g = flow_geometry(h);
  Chart c{"flow_pattern_chart", "Mass-flow limit against wall friction", {"wall friction angle", "deg"},
          {"hopper semi-angle", "deg"}, {}, ""};
  const double delta = m.flow.effective_friction_angle;
  ChartSeries band{"limit band", SeriesStyle::band, {}, {}, {}, 0};
  ChartSeries line{"mass-flow limit", SeriesStyle::line, {}, {}, {}, 0};
  for (double phi : range(0.0, std::min(delta - 1.0 * kDegree, 45.0 * kDegree), 30)) {
    const auto limit = mass_flow_limit(g, delta, phi);
    band.x.push_back(phi / kDegree);
    band.y.push_back(limit.low / kDegree);
    band.y_upper.push_back(limit.high / kDegree);
    line.x.push_back(phi / kDegree);
    line.y.push_back(limit.nominal / kDegree);
  }
  c.series = {band, line,
              {"design point", SeriesStyle::marker, {*h.wall_friction_angle / kDegree}, {h.semi_angle / kDegree}, {}, 6}};
  c.note = "Below the line: mass flow; above it: funnel flow. " + pattern.limit.model + ".";
  return c;
}

Chart stress_chart(const Hopper& h, const HopperMaterial& m, const double design_density) {
  Chart c{"stresses_while_emptying", "Stresses while emptying (Janssen bin, hopper slice)", {"stress", "kPa"},
          {"height above the apex", "m"}, {}, ""};
  const auto profile = emptying_silo_profile(h, design_density, m.flow.effective_friction_angle,
                                             *h.wall_friction_angle, StressRatioRule::schulze);
  ChartSeries vertical{"mean vertical stress", SeriesStyle::line, {}, {}, {}};
  ChartSeries normal{"wall normal stress", SeriesStyle::dashed, {}, {}, {}};
  for (const auto& p : profile) {
    vertical.x.push_back(p.vertical / 1e3);
    vertical.y.push_back(p.height);
    normal.x.push_back(p.wall_normal / 1e3);
    normal.y.push_back(p.height);
  }
  c.series = {vertical, normal};
  c.note = "Emptying state with a constant bulk density; the wall normal stress jumps at the transition (switch "
           "stress). Structural loads need EN 1991-4, which this chart does not replace.";
  return c;
}

// Emptying at the steady rate, with the band's rates: a constant rate until the hopper is empty.
Chart emptying_chart(double content, double rate, const Band& total) {
  Chart emptying{"discharged_mass_vs_time", "Discharged mass against time", {"time", "s"},
                 {"discharged mass", "kg"}, {}, ""};
  const double end = 1.2 * content / (total.low > 0.0 ? total.low : rate);  // the time axis
  for (const auto& [label, q, style] : {std::tuple{"steady discharge", rate, SeriesStyle::line},
                                        std::tuple{"band, low rate", total.low, SeriesStyle::dashed},
                                        std::tuple{"band, high rate", total.high, SeriesStyle::dashed}}) {
    if (!(q > 0.0)) {  // a band reaching zero: an outlet that arches discharges nothing
      emptying.series.push_back({label, style, {0.0, end}, {0.0, 0.0}, {}});
      continue;
    }
    const double empty_at = content / q;
    emptying.series.push_back({label, style, {0.0, empty_at, std::max(end, empty_at)}, {0.0, content, content}, {}});
  }
  emptying.note = "Reduced model: a constant rate until the hopper is empty; a simulation shows the start-up and "
                  "the end of discharge.";
  return emptying;
}

}  // namespace

std::vector<Chart> hopper_charts(const Material& material, const Hopper& h, const HopperAssessment& a) {
  const HopperMaterial& m = a.material;
  const HopperEvaluation& nominal = a.nominal();
  std::vector<Chart> charts{outlet_against_angle(h, m, a.models, a.pattern),
                            flow_function_chart(m, a), rate_against_outlet(h, m, a.models, nominal),
                            pattern_chart(h, m, a.pattern)};
  charts.push_back(stress_chart(h, m, nominal.johanson.bulk_density));
  const double length = h.is_wedge() ? *h.slot_length : 1.0;
  const double rate = nominal.rate * length, content = material.bulk.density * h.filled_volume();
  if (rate > 0.0) charts.push_back(emptying_chart(content, rate, a.rate.scaled(length)));
  return charts;
}

}  // namespace feedflow
