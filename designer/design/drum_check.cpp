#include "designer/design/drum_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include "designer/design/judge.hpp"
#include "designer/design/target_units.hpp"
#include "designer/design/verdict_builder.hpp"
#include "models/chute/mu_i_rheology.hpp"
#include "models/core/band.hpp"
#include "models/core/errors.hpp"
#include "models/drum/rolling_layer.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

// The flowing layer of the material: mu(I) matched to its Pouliquen law (theta1 and theta2
// shifted by `friction_shift`) mid-way between theta1 and theta2, grains of size d50.
RollingLayerModel layer_model(const Material& m, double layer_fraction, double friction_shift) {
  const auto& s = *m.surface_flow;
  const PouliquenLaw law{s.theta1 + friction_shift, s.theta2 + friction_shift, s.stop_length,
                         s.flow_rule_beta, s.flow_rule_gamma};
  const double d = m.psd ? m.psd->d50 : 1e-3;
  return {mu_i_from_pouliquen(law, d, s.solid_fraction, 0.5 * (law.theta1 + law.theta2), FroudeConvention::SqrtGH),
          layer_fraction, m.drum_flow->end_wall_friction};
}

// Fr over the Fr of the nearest regime boundary (by the ratio), and that boundary in words.
std::pair<double, std::string> nearest_boundary(double froude, const DrumRegimeThresholds& t) {
  double nearest = 1e9;
  std::pair<double, std::string> out{1e9, "none"};
  for (const auto& [name, fr] : regime_boundaries(t))
    if (std::abs(std::log(froude / fr)) < nearest) {
      nearest = std::abs(std::log(froude / fr));
      out = {froude / fr, std::string(name) + " at Fr = " + format_number(fr)};
    }
  return out;
}

void regime_results(const DrumRegimeThresholds& t, const DrumRegimeAssessment& regime, Estimates& results) {
  results.emplace_back("regime", labelled(to_string(regime.regime), "Froude-number thresholds calibrated for the material"));
  results.emplace_back("froude_number", unbanded(regime.froude, "", "Fr = omega^2 R / g", Rung::L0));
  const auto [ratio, boundary] = nearest_boundary(regime.froude, t);
  results.emplace_back("regime_boundary_ratio",
                       unbanded(ratio, "", "Fr over the Fr of the nearest regime boundary (" + boundary + ")", Rung::L0));
  results.emplace_back("critical_speed", unbanded(regime.critical_speed / kRpm, "rpm", "n_c = sqrt(2 g / D)", Rung::L0));
  results.emplace_back("full_bed_centrifuging_speed",
                       unbanded(regime.critical_speed * std::sqrt(regime.full_bed_centrifuging_froude) / kRpm, "rpm",
                                "Fr = 1/sqrt(1 - f) at the bed's inner radius", Rung::L0));
}

std::string angle_model_text(const DrumLayer& layer) {
  if (!layer.calibration) return "mu(I) flowing layer with end-wall friction";
  return "mu(I) flowing layer with end-wall friction, calibrated (c_delta " +
         format_number(layer.layer_fraction, 3) + ", friction shift " +
         format_quantity(layer.friction_shift, "deg", 3) + ")";
}

// The angle of repose in the rolling regime, and the wall friction the bed needs not to slip.
void angle_results(const Drum& drum, const Material& m, const DrumRegimeThresholds& t, Estimates& results) {
  const AngleOfRepose angle = rolling_angle_band(drum, m);
  results.emplace_back("dynamic_angle_of_repose",
                       Estimate{angle.nominal / kDegree, "deg", angle.low / kDegree,
                                angle.high / kDegree, angle_model_text(drum_layer(m)), Rung::L0,
                                ""});
  Band slip;
  for (double a : {angle.low, angle.high}) slip.add(assess_drum_regime(drum, t, a).no_slip_friction);
  results.emplace_back("no_slip_wall_friction",
                       banded(assess_drum_regime(drum, t, angle.nominal).no_slip_friction, "", slip,
                              "(r_g/R) sin(beta_d): the least tan(wall friction) for no slip at the shell", Rung::L0));
}

// Where `drum` lies beyond the calibrated drum (diameter or fill more than 10 % off), in words;
// empty within it or when the table did not record it.
std::string beyond_calibration(const Drum& drum, const DrumCalibration& c) {
  std::string out;
  if (c.diameter && std::abs(drum.diameter / *c.diameter - 1.0) > 0.1)
    out = "diameter " + format_quantity(drum.diameter, "mm", 4) + " against " +
          format_quantity(*c.diameter, "mm", 4);
  if (c.fill_fraction && std::abs(drum.fill_fraction / *c.fill_fraction - 1.0) > 0.1)
    out += (out.empty() ? "" : ", ") + std::string("fill ") +
           format_number(100.0 * drum.fill_fraction, 3) + " % against " +
           format_number(100.0 * *c.fill_fraction, 3) + " %";
  return out;
}

std::vector<std::string> drum_assumptions(const Drum& drum, const DrumRegimeThresholds& t,
                                          const DrumLayer& layer) {
  std::vector<std::string> out = {
      "Regime thresholds are calibration targets in Froude number (not Mellmann's recalled bands): "
      "rolling to cascading at Fr = " +
          format_number(t.rolling_to_cascading) +
          ", cascading to cataracting at Fr = " + format_number(t.cascading_to_cataracting) + ".",
      "The angle of repose comes from a mu(I) flowing layer whose thickness is a fixed fraction of "
      "the half-chord; it is a mid-chord slope and ignores the S-shape of faster regimes."};
  if (const DrumCalibration* c = layer.calibration) {
    std::string figures;
    for (const auto& [name, text] : c->layer.figures)
      if (name.find("_before") == std::string::npos)
        figures += (figures.empty() ? "" : ", ") + name + " " + text;
    out.push_back(
        "The flowing layer is the material's [calibration.drum]: c_delta " +
        format_number(layer.layer_fraction, 3) + " and theta1, theta2 shifted by " +
        format_quantity(layer.friction_shift, "deg", 3) + ", fitted to " + c->rung + " over " +
        std::to_string(c->points) + " drum speeds of " + c->scene + " (commit " + c->commit + ", " +
        c->date + (figures.empty() ? "" : "; " + figures) + "); the band is widened by " +
        format_number(100.0 * layer.error, 3) + " %" +
        (c->end_walls
             ? "."
             : "; fitted without end walls (a plane slice), this drum's end-wall friction added."));
    if (const std::string beyond = beyond_calibration(drum, *c); !beyond.empty())
      out.push_back("This drum lies outside the calibrated one (" + beyond +
                    "): the fitted flowing layer is extrapolated to it.");
  } else {
    out.push_back("The flowing layer's c_delta = " + format_number(layer.layer_fraction, 3) +
                  " is the published mid value (0.1-0.3), not calibrated: `feedflow calibrate "
                  "MATERIAL --against cel --case DRUM_CASE` fits it to the continuum rung.");
  }
  return out;
}

}  // namespace

DrumRegimeThresholds regime_thresholds(const DrumFlowProperties& d) {
  return {d.froude_slumping_to_rolling, d.froude_rolling_to_cascading, d.froude_cascading_to_cataracting, 1.0};
}

DrumLayer drum_layer(const Material& m) {
  if (m.calibration && m.calibration->drum) {
    const DrumCalibration& c = *m.calibration->drum;
    return {c.layer.coefficients.at("layer_fraction"), c.layer.coefficients.at("friction_shift"),
            largest_error(c.layer).value_or(0.0), &c};
  }
  return {m.drum_flow->layer_fraction, 0.0, 0.0, nullptr};
}

AngleOfRepose rolling_angle_band(const Drum& drum, const Material& m) {
  const auto& d = *m.drum_flow;
  const DrumLayer layer = drum_layer(m);
  const auto angle = [&](double fraction, double shift) {
    return rolling_angle_of_repose(drum, layer_model(m, fraction, shift)).angle_of_repose;
  };
  const double nominal = angle(layer.layer_fraction, layer.friction_shift);
  double low = nominal, high = nominal;
  const double u = m.surface_flow->theta_uncertainty;
  // Published: over the plausible layer thickness and theta's uncertainty. Calibrated: over
  // theta's uncertainty at the fitted thickness, widened by the calibration's largest error.
  std::vector<double> fractions = {d.layer_fraction_low, d.layer_fraction_high};
  if (layer.calibration) fractions = {layer.layer_fraction};
  for (double fraction : fractions)
    for (double shift : {-u, u}) {
      const double a = angle(fraction, layer.friction_shift + shift);
      low = std::min(low, a);
      high = std::max(high, a);
    }
  low = std::min(low, nominal * (1.0 - layer.error));
  high = std::max(high, nominal * (1.0 + layer.error));
  return {nominal, low, high};
}

void check_drum(const Case& c, const Drum& drum, DesignDetail detail, DesignRecord& record) {
  const Material& m = c.material;
  if (!m.drum_flow)
    throw InputError(m.origin, "material.drum_flow",
                     "the drum models need the material's regime thresholds ([drum_flow]); material " + m.name +
                         " has none");
  const DrumRegimeThresholds thresholds = regime_thresholds(*m.drum_flow);
  const DrumRegimeAssessment regime = assess_drum_regime(drum, thresholds);
  regime_results(thresholds, regime, record.results);
  const bool rolling = regime.regime == DrumRegime::Rolling;
  if (rolling && m.surface_flow) angle_results(drum, m, thresholds, record.results);
  VerdictBuilder verdict;
  show_in_target_units(c, record.results);
  for (auto& f : judge_drum(drum, c.design, record.results).findings) verdict.add(std::move(f));
  if (!rolling)
    verdict.add(Finding{std::nullopt, "dynamic_angle_of_repose",
                        "the dynamic angle of repose model holds in the rolling regime only; this drum is " +
                            std::string(to_string(regime.regime))});
  record.verdict = verdict.verdict();
  if (detail == DesignDetail::results) return;
  record.charts = drum_charts(drum, m, regime);
  record.assumptions = drum_assumptions(drum, thresholds, drum_layer(m));
}

}  // namespace feedflow
