#include "designer/design/drum_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "models/chute/mu_i_rheology.hpp"
#include "models/core/errors.hpp"
#include "models/drum/drum_regime.hpp"
#include "models/drum/rolling_layer.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;

DrumRegimeThresholds thresholds_of(const DrumFlowProperties& d) {
  return {d.froude_slumping_to_rolling, d.froude_rolling_to_cascading, d.froude_cascading_to_cataracting, 1.0};
}

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

Estimate label(std::string value, std::string model) {
  return Estimate{std::move(value), "", std::nullopt, std::nullopt, std::move(model), Rung::L0, ""};
}

}  // namespace

void check_drum(const Case& c, const Drum& drum, DesignRecord& record, VerdictBuilder& verdict) {
  const Material& m = c.material;
  if (!m.drum_flow)
    throw InputError(m.origin, "material.drum_flow",
                     "the drum models need the material's regime thresholds ([drum_flow]); material " + m.name +
                         " has none");
  const DrumRegimeThresholds thresholds = thresholds_of(*m.drum_flow);
  const DrumRegimeAssessment regime = assess_drum_regime(drum, thresholds);
  auto& results = record.results;
  const std::string regime_model = "Froude-number thresholds calibrated for the material";
  results.emplace_back("regime", label(to_string(regime.regime), regime_model));
  results.emplace_back("froude_number", Estimate{regime.froude, "", std::nullopt, std::nullopt,
                                                 "Fr = omega^2 R / g", Rung::L0, ""});
  results.emplace_back("critical_speed", Estimate{regime.critical_speed / kRpm, "rpm", std::nullopt, std::nullopt,
                                                  "n_c = sqrt(2 g / D)", Rung::L0, ""});
  results.emplace_back("full_bed_centrifuging_speed",
                       Estimate{regime.critical_speed * std::sqrt(regime.full_bed_centrifuging_froude) / kRpm, "rpm",
                                std::nullopt, std::nullopt, "Fr = 1/sqrt(1 - f) at the bed's inner radius",
                                Rung::L0, ""});

  std::optional<double> angle;
  if (regime.regime == DrumRegime::Rolling && m.surface_flow) {
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
    angle = nominal;
    results.emplace_back("dynamic_angle_of_repose",
                         Estimate{nominal / kDeg, "deg", low / kDeg, high / kDeg,
                                  "mu(I) flowing layer with end-wall friction", Rung::L0, ""});
    // Angle of repose against speed over the rolling range.
    Chart chart{"angle_of_repose_vs_speed", "Dynamic angle of repose against speed (rolling regime)",
                {"drum speed", "rpm"}, {"dynamic angle of repose", "deg"}, {}, ""};
    ChartSeries band{"uncertainty band", SeriesStyle::band, {}, {}, {}, 0};
    ChartSeries line{"mu(I) flowing layer", SeriesStyle::line, {}, {}, {}, 0};
    const double top = regime.critical_speed * std::sqrt(thresholds.rolling_to_cascading);
    const double bottom = regime.critical_speed * std::sqrt(thresholds.slumping_to_rolling) * 1.05;
    for (int i = 0; i < 30; ++i) {
      Drum at = drum;
      at.speed = bottom + (top - bottom) * i / 29.0;
      const double a = rolling_angle_of_repose(at, layer_model(m, d.layer_fraction)).angle_of_repose;
      double lo = a, hi = a;
      for (double fraction : {d.layer_fraction_low, d.layer_fraction_high})
        for (double shift : {-u, u}) {
          const double b = rolling_angle_of_repose(at, layer_model(m, fraction, shift)).angle_of_repose;
          lo = std::min(lo, b);
          hi = std::max(hi, b);
        }
      line.x.push_back(at.speed / kRpm);
      line.y.push_back(a / kDeg);
      band.x.push_back(at.speed / kRpm);
      band.y.push_back(lo / kDeg);
      band.y_upper.push_back(hi / kDeg);
    }
    chart.series = {band, line, {"design speed", SeriesStyle::marker, {drum.speed / kRpm}, {nominal / kDeg}, {}, 6}};
    chart.note = "The band spans the flowing-layer thickness (c_delta) and +- the uncertainty of theta1 and theta2.";
    record.charts.push_back(std::move(chart));
  } else if (regime.regime != DrumRegime::Rolling) {
    verdict.note("the dynamic angle of repose model holds in the rolling regime only; this drum is " +
                 std::string(to_string(regime.regime)));
  }

  // Regime map: Froude number against speed with the thresholds.
  Chart map{"drum_regime_map", "Drum regime map", {"drum speed", "rpm"}, {"Froude number", "", true}, {}, ""};
  ChartSeries froude{"Fr of this drum", SeriesStyle::line, {}, {}, {}};
  const double n_max = std::max(1.5 * regime.critical_speed, 1.2 * drum.speed);
  for (int i = 1; i <= 60; ++i) {
    const double n = n_max * i / 60.0;
    froude.x.push_back(n / kRpm);
    froude.y.push_back(drum_froude(drum.diameter, n));
  }
  map.series.push_back(froude);
  const std::pair<const char*, double> lines[] = {{"slumping | rolling", thresholds.slumping_to_rolling},
                                                  {"rolling | cascading", thresholds.rolling_to_cascading},
                                                  {"cascading | cataracting", thresholds.cascading_to_cataracting},
                                                  {"centrifuging (outer layer)", thresholds.centrifuging}};
  for (const auto& [name, fr] : lines)
    map.series.push_back({name, SeriesStyle::dashed, {0.0, n_max / kRpm}, {fr, fr}, {}});
  map.series.push_back({"design speed", SeriesStyle::marker, {drum.speed / kRpm}, {regime.froude}, {}, 6});
  map.note = "Regime boundaries are material thresholds on Fr = (n/n_c)^2; the whole bed centrifuges from "
             "Fr = 1/sqrt(1 - f).";
  record.charts.push_back(std::move(map));

  // Verdict.
  const std::string got = to_string(regime.regime);
  const std::string required = c.design.required_regime;
  // How close the speed sits to the nearest regime boundary, as a ratio of Froude numbers.
  double nearest = 1e9;
  for (const auto& [name, fr] : lines) nearest = std::min(nearest, std::abs(std::log(regime.froude / fr)));
  const bool near_boundary = nearest < std::log(1.25);
  const std::string text = got + " at " + format_quantity(drum.speed, "rpm", 3) + " (Fr = " +
                           format_number(regime.froude, 3) + ")";
  if (required == "any")
    verdict.note(text);
  else if (got != required)
    verdict.fail(required + " required, but the drum runs " + text);
  else if (near_boundary)
    verdict.marginal(text + ", within 25 % of a regime boundary in Fr");
  else
    verdict.pass(text + " as required");
  if (regime.full_bed_centrifuges) verdict.note("the whole bed centrifuges: " + regime.words);
  if (angle) {
    const auto with_angle = assess_drum_regime(drum, thresholds, angle);
    if (with_angle.wall_slips && *with_angle.wall_slips)
      verdict.marginal("the bed may slip at the shell: wall friction below (r_g/R) sin(beta_d) = " +
                       format_number(with_angle.no_slip_friction, 3));
  }
  record.assumptions.push_back("Regime thresholds are calibration targets in Froude number (not Mellmann's recalled "
                               "bands): rolling to cascading at Fr = " + format_number(thresholds.rolling_to_cascading) +
                               ", cascading to cataracting at Fr = " + format_number(thresholds.cascading_to_cataracting) + ".");
  record.assumptions.push_back("The angle of repose comes from a mu(I) flowing layer whose thickness is a fixed fraction "
                               "of the half-chord; it is a mid-chord slope and ignores the S-shape of faster regimes.");
}

}  // namespace feedflow
