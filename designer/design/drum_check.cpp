#include "designer/design/drum_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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

// The flowing layer of the material: mu(I) matched to its Pouliquen law mid-way between theta1
// and theta2, grains of size d50.
RollingLayerModel layer_model(const Material& m, double layer_fraction, double theta_shift = 0.0) {
  const auto& s = *m.surface_flow;
  const PouliquenLaw law{s.theta1 + theta_shift, s.theta2 + theta_shift, s.stop_length, s.flow_rule_beta,
                         s.flow_rule_gamma};
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

// The angle of repose in the rolling regime, and the wall friction the bed needs not to slip.
void angle_results(const Drum& drum, const Material& m, const DrumRegimeThresholds& t, Estimates& results) {
  const AngleOfRepose angle = rolling_angle_band(drum, m);
  results.emplace_back("dynamic_angle_of_repose",
                       Estimate{angle.nominal / kDegree, "deg", angle.low / kDegree, angle.high / kDegree,
                                "mu(I) flowing layer with end-wall friction", Rung::L0, ""});
  Band slip;
  for (double a : {angle.low, angle.high}) slip.add(assess_drum_regime(drum, t, a).no_slip_friction);
  results.emplace_back("no_slip_wall_friction",
                       banded(assess_drum_regime(drum, t, angle.nominal).no_slip_friction, "", slip,
                              "(r_g/R) sin(beta_d): the least tan(wall friction) for no slip at the shell", Rung::L0));
}

std::vector<std::string> drum_assumptions(const DrumRegimeThresholds& t) {
  return {"Regime thresholds are calibration targets in Froude number (not Mellmann's recalled bands): rolling to "
          "cascading at Fr = " + format_number(t.rolling_to_cascading) + ", cascading to cataracting at Fr = " +
              format_number(t.cascading_to_cataracting) + ".",
          "The angle of repose comes from a mu(I) flowing layer whose thickness is a fixed fraction of the "
          "half-chord; it is a mid-chord slope and ignores the S-shape of faster regimes."};
}

}  // namespace

DrumRegimeThresholds regime_thresholds(const DrumFlowProperties& d) {
  return {d.froude_slumping_to_rolling, d.froude_rolling_to_cascading, d.froude_cascading_to_cataracting, 1.0};
}

AngleOfRepose rolling_angle_band(const Drum& drum, const Material& m) {
  const auto& d = *m.drum_flow;
  const double nominal = rolling_angle_of_repose(drum, layer_model(m, d.layer_fraction)).angle_of_repose;
  double low = nominal, high = nominal;
  const double u = m.surface_flow->theta_uncertainty;
  for (double fraction : {d.layer_fraction_low, d.layer_fraction_high})
    for (double shift : {-u, u}) {
      const double a = rolling_angle_of_repose(drum, layer_model(m, fraction, shift)).angle_of_repose;
      low = std::min(low, a);
      high = std::max(high, a);
    }
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
  record.assumptions = drum_assumptions(thresholds);
}

}  // namespace feedflow
