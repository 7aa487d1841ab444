// The drum's report charts (drum_check.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "designer/design/drum_check.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

// Angle of repose against speed over the rolling range.
Chart angle_against_speed(const Drum& drum, const Material& m, const DrumRegimeAssessment& regime) {
  const DrumRegimeThresholds thresholds = regime_thresholds(*m.drum_flow);
  Chart chart{"angle_of_repose_vs_speed", "Dynamic angle of repose against speed (rolling regime)",
              {"drum speed", "rpm"}, {"dynamic angle of repose", "deg"}, {}, ""};
  ChartSeries band{"uncertainty band", SeriesStyle::band, {}, {}, {}, 0};
  ChartSeries line{"mu(I) flowing layer", SeriesStyle::line, {}, {}, {}, 0};
  const double top = regime.critical_speed * std::sqrt(thresholds.rolling_to_cascading);
  const double bottom = regime.critical_speed * std::sqrt(thresholds.slumping_to_rolling) * 1.05;
  for (int i = 0; i < 30; ++i) {
    Drum at = drum;
    at.speed = bottom + (top - bottom) * i / 29.0;
    const AngleOfRepose a = rolling_angle_band(at, m);
    line.x.push_back(at.speed / kRpm);
    line.y.push_back(a.nominal / kDegree);
    band.x.push_back(at.speed / kRpm);
    band.y.push_back(a.low / kDegree);
    band.y_upper.push_back(a.high / kDegree);
  }
  const double design = rolling_angle_band(drum, m).nominal;
  chart.series = {band, line, {"design speed", SeriesStyle::marker, {drum.speed / kRpm}, {design / kDegree}, {}, 6}};
  chart.note = "The band spans the flowing-layer thickness (c_delta) and +- the uncertainty of theta1 and theta2.";
  return chart;
}

// Regime map: Froude number against speed with the thresholds.
Chart regime_map(const Drum& drum, const DrumRegimeThresholds& thresholds, const DrumRegimeAssessment& regime) {
  Chart map{"drum_regime_map", "Drum regime map", {"drum speed", "rpm"}, {"Froude number", "", true}, {}, ""};
  ChartSeries froude{"Fr of this drum", SeriesStyle::line, {}, {}, {}};
  const double n_max = std::max(1.5 * regime.critical_speed, 1.2 * drum.speed);
  for (int i = 1; i <= 60; ++i) {
    const double n = n_max * i / 60.0;
    froude.x.push_back(n / kRpm);
    froude.y.push_back(drum_froude(drum.diameter, n));
  }
  map.series.push_back(froude);
  for (const auto& [name, fr] : regime_boundaries(thresholds))
    map.series.push_back({name, SeriesStyle::dashed, {0.0, n_max / kRpm}, {fr, fr}, {}});
  map.series.push_back({"design speed", SeriesStyle::marker, {drum.speed / kRpm}, {regime.froude}, {}, 6});
  map.note = "Regime boundaries are material thresholds on Fr = (n/n_c)^2; the whole bed centrifuges from "
             "Fr = 1/sqrt(1 - f).";
  return map;
}

}  // namespace

std::vector<Chart> drum_charts(const Drum& drum, const Material& m, const DrumRegimeAssessment& regime) {
  std::vector<Chart> charts;
  if (regime.regime == DrumRegime::Rolling && m.surface_flow) charts.push_back(angle_against_speed(drum, m, regime));
  charts.push_back(regime_map(drum, regime_thresholds(*m.drum_flow), regime));
  return charts;
}

}  // namespace feedflow
