// The chute's report charts (chute_check.hpp).
#include <algorithm>
#include <numbers>

#include "designer/design/chute_check.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

Chart stop_against_angle(const Chute& chute, const Material& m, const StoppingThicknessModel& stop) {
  const auto& s = *m.surface_flow;
  Chart c{"stopping_thickness_vs_angle", "Stopping thickness against chute angle", {"chute angle", "deg"},
          {"stopping thickness", "mm"}, {}, ""};
  ChartSeries band{"uncertainty band", SeriesStyle::band, {}, {}, {}, 0};
  ChartSeries line{"h_stop", SeriesStyle::line, {}, {}, {}, 0};
  const auto laws = corner_laws(s);
  const double from = s.theta1 + 0.25 * (s.theta2 - s.theta1) * 0.5, to = s.theta2;
  for (int i = 0; i < 40; ++i) {
    const double angle = from + (to - from) * i / 39.0;
    const auto nominal = stop.evaluate(pouliquen_law_of(s), m, angle);
    if (nominal.outcome != DepositOutcome::Deposit) continue;
    double lo = nominal.thickness, hi = nominal.thickness;
    for (const auto& law : laws) {
      const auto t = stop.evaluate(law, m, angle);
      if (t.outcome == DepositOutcome::Deposit) {
        lo = std::min(lo, t.thickness);
        hi = std::max(hi, t.thickness);
      }
    }
    band.x.push_back(angle / kDegree);
    band.y.push_back(lo * 1e3);
    band.y_upper.push_back(std::min(hi, 5 * nominal.thickness) * 1e3);
    line.x.push_back(angle / kDegree);
    line.y.push_back(nominal.thickness * 1e3);
  }
  c.series = {band, line};
  const auto design = stop.evaluate(pouliquen_law_of(s), m, chute.angle);
  if (design.outcome == DepositOutcome::Deposit)
    c.series.push_back({"design angle", SeriesStyle::marker, {chute.angle / kDegree}, {design.thickness * 1e3}, {}, 6});
  c.note = "No layer stops above theta2; below theta1 nothing flows. The band spans the uncertainty of theta1, "
           "theta2 and L (upper edge clipped at 5 x the nominal value).";
  return c;
}

Chart deposit_profile(const Chute& chute, const RampFlowResult& run, double h_stop) {
  Chart profile{"deposit_profile", "Deposit along the ramp once flow stops (L1)", {"distance from the gate", "m"},
                {"deposit thickness", "mm"}, {}, ""};
  ChartSeries h{"deposit (L1)", SeriesStyle::line, {}, {}, {}};
  for (std::size_t i = 0; i < run.x.size(); ++i) {
    if (run.x[i] < 0) continue;  // inside the bin
    h.x.push_back(run.x[i]);
    h.y.push_back(run.thickness[i] * 1e3);
  }
  profile.series = {h, {"h_stop (L0)", SeriesStyle::dashed, {0.0, chute.length}, {h_stop * 1e3, h_stop * 1e3}, {}},
                    {"mid-ramp", SeriesStyle::marker, {chute.length / 2}, {run.probe_thickness * 1e3}, {}, 6}};
  profile.note = "Second-order well-balanced scheme on 10 mm cells; the seed measured h_stop at mid-ramp.";
  return profile;
}

// The front position and the velocities against time.
std::pair<Chart, Chart> release_histories(const RampFlowResult& run) {
  Chart front{"front_position", "Front position against time (L1)", {"time", "s"}, {"front position", "m"}, {}, ""};
  ChartSeries f{"front", SeriesStyle::line, {}, {}, {}};
  Chart speed{"velocity_vs_time", "Depth-averaged velocity against time (L1)", {"time", "s"},
              {"velocity", "m/s"}, {}, ""};
  ChartSeries mean{"mean on the ramp", SeriesStyle::line, {}, {}, {}};
  ChartSeries at_front{"at the front", SeriesStyle::dashed, {}, {}, {}};
  for (const auto& sample : run.samples) {
    f.x.push_back(sample.time);
    f.y.push_back(sample.front_position);
    mean.x.push_back(sample.time);
    mean.y.push_back(sample.mean_velocity);
    at_front.x.push_back(sample.time);
    at_front.y.push_back(sample.front_velocity);
  }
  front.series = {f};
  front.note = "Distance of the farthest material from the gate; it reaches the ramp end when material leaves.";
  speed.series = {mean, at_front};
  speed.note = "Volume-weighted depth-averaged velocity on the ramp and the velocity at the front.";
  return {std::move(front), std::move(speed)};
}

}  // namespace

std::vector<Chart> chute_charts(const Chute& chute, const Material& m, const StoppingThicknessModel& stop,
                                const std::optional<ChuteDeposit>& deposit) {
  std::vector<Chart> charts{stop_against_angle(chute, m, stop)};
  if (deposit) {
    const double h_stop = stop.evaluate(pouliquen_law_of(*m.surface_flow), m, chute.angle).thickness;
    auto [front, speed] = release_histories(deposit->run);
    charts.push_back(std::move(speed));
    charts.push_back(deposit_profile(chute, deposit->run, h_stop));
    charts.push_back(std::move(front));
  }
  return charts;
}

}  // namespace feedflow
