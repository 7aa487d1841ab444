#include "designer/simulate/hopper_discharge.hpp"

#include <cstdio>
#include <limits>

#include "models/core/printf_format.hpp"

namespace feedflow {
namespace {

constexpr double kConvergedHalfWidth = 0.05;  // the rate's interval within +-5 % ends the run
constexpr std::size_t kConvergedBatches = 10;
constexpr double kMinPatternWindow = 0.1;  // [s] the least time the flow line is averaged over

SteadyRateSettings rate_settings() {
  SteadyRateSettings r;
  r.batch_duration = 0.05;
  r.min_batches = 5;
  return r;
}

}  // namespace

HopperDischarge::Rows discharge_rows(const TimeSeries& series, std::size_t time, std::size_t discharged,
                                     std::size_t mass_left, std::size_t kinetic_energy) {
  HopperDischarge::Rows r;
  for (const auto& row : series.rows()) {
    r.time.push_back(row[time]);
    r.discharged.push_back(row[discharged]);
  }
  if (!series.empty()) {
    r.mass_left = series.rows().back()[mass_left];
    r.kinetic_energy = series.rows().back()[kinetic_energy];
  }
  return r;
}

SteadyRate HopperDischarge::steady_rate(const Rows& rows) const {
  return steady_discharge_rate(rows.time, rows.discharged, opening, rate_settings());
}

DischargeState HopperDischarge::state(const Rows& rows) const {
  if (rows.time.empty()) return DischargeState::flowing;
  const double last = last_discharge_time(rows.time, rows.discharged, opening, trickle_rate);
  return discharge_state(rows.time.back(), last, rows.kinetic_energy, rows.mass_left,
                         fill_mass > 0.0 ? rows.mass_left / fill_mass : 1.0, arch);
}

std::string HopperDischarge::stop_reason(const Rows& rows) const {
  const DischargeState s = state(rows);
  char text[300];
  if (s == DischargeState::arched) {
    std::snprintf(text, sizeof text,
                  "arched: less than %.3g kg/s out for %.3g s and the kinetic energy below that of the "
                  "fill moving at %.3g m/s", trickle_rate, arch.quiet_time, arch.speed);
    return text;
  }
  if (s == DischargeState::emptied) return "the hopper has emptied";
  const SteadyRate r = steady_rate(rows);
  const bool long_enough = !rows.time.empty() && rows.time.back() - opening >= earliest_convergence;
  if (r.found && long_enough && r.batches >= kConvergedBatches && r.high - r.low < 2.0 * kConvergedHalfWidth * r.rate)
    return "converged: the steady rate's 95 % interval is within +-5 %";
  return "";
}

std::string HopperDischarge::describe() const {
  return format("arched when less than %.3g kg/s (%.3g of %s) leaves for %.3g s and the kinetic "
                "energy is below 1/2 M (%.3g m/s)^2; emptied below %.3g of the fill",
                trickle_rate, arch.trickle_share, scale_rate.c_str(), arch.quiet_time, arch.speed, arch.empty_fraction);
}

SteadyRate add_discharge_results(const HopperDischarge& d, const HopperDischarge::Rows& rows,
                                 const SpeedProfileSeries& flow_line, const DischargeWording& w,
                                 DesignRecord& record) {
  const SteadyRate rate = d.steady_rate(rows);
  const DischargeState state = d.state(rows);
  const bool arched = state == DischargeState::arched;
  auto& results = record.results;
  if (arched)  // an arch ends the flow: no steady rate, whatever dribbled out before it
    results.emplace_back("mass_flow_rate", Estimate{0.0, "kg/s", 0.0, 0.0, w.rate_source + w.arched_detail, w.rung, ""});
  else if (rate.found)
    results.emplace_back("mass_flow_rate", Estimate{rate.rate * w.scale, "kg/s", rate.low * w.scale, rate.high * w.scale,
                                                    w.rate_source + "; steady window " + rate.describe() + w.steady_detail,
                                                    w.rung, ""});
  else
    record.verdict.reasons.push_back("no steady discharge window yet: run longer (--time)");
  results.emplace_back("arching", Estimate{to_string(state), "", std::nullopt, std::nullopt, w.model + "; " + d.describe(),
                                           w.rung, ""});
  // The flow pattern from the speeds across the converging section at mid-height, over the
  // steady window (the whole run without one); when the falling surface (or a crater) reached
  // the line within the window, over the window's part before it.
  const double from = rate.found ? rate.window_start : w.pattern_from;
  const double to = rate.found ? rate.window_end : std::numeric_limits<double>::infinity();
  WallSpeedRatio ratio = flow_line.ratio(from, to);
  const std::string span = rate.found ? "the steady window" : "the run";
  std::string window = span;
  bool cut = false;  // the window ends where the line emptied
  if (!ratio.measured) {
    const double until = flow_line.covered_until(from, to);
    if (until - from >= kMinPatternWindow) {
      ratio = flow_line.ratio(from, until);
      window = format("t = %.3g-%.3g s, %s until the line emptied", from, until, span.c_str());
      cut = true;
    }
  }
  if (!arched && !ratio.measured)
    record.verdict.reasons.push_back(format(
        "flow pattern not measured: the line across the converging section at mid-height did "
        "not hold material with a moving centre for %.3g s of %s",
        kMinPatternWindow, span.c_str()));
  if (!arched && ratio.measured) {
    results.emplace_back("flow_pattern", Estimate{ratio.label(), "", std::nullopt, std::nullopt,
                                                  w.pattern_source + (cut ? " (here " + window + ")" : ""),
                                                  w.rung, ""});
    results.emplace_back("wall_to_centre_speed_ratio",
                         Estimate{ratio.ratio, "", std::nullopt, std::nullopt,
                                  w.speeds + " at mid-height of the converging section, averaged over " + window,
                                  w.rung, ""});
    results.emplace_back(
        "stagnant_zone_width",
        Estimate{ratio.stagnant_width * 1e3, "mm", std::nullopt, std::nullopt,
                 "band at the wall moving slower than a tenth of the centre line, on the "
                 "same line and window (0: the material at the wall moves)",
                 w.rung, ""});
  }
  return arched ? SteadyRate{} : rate;
}

}  // namespace feedflow
