#pragma once
// Measurements of a discharge through an outlet sink, scene-independent (hopper, bin, silo):
// the cumulative discharged mass against time, the steady mass flow rate with a confidence
// interval from an automatically detected steady window, and the arching test.
//
// Steady window: the cumulative mass is cut into batches of equal duration and each batch's
// rate dm/dt taken. The start-up transient and the emptying tail are dropped by the MSER rule
// (White 1997: keep the truncation that minimises the squared standard error of the mean of
// what is left, var / (n - d)^2), taken over both ends at once (each at most half the batches). The rate is the mean of the kept batch rates (= the secant slope of the
// window); its interval is the batch-means t interval (GSL t quantile). Batch means rather
// than the regression error of m(t): the residuals of a cumulative curve are correlated and
// would understate the error.
#include <cstddef>
#include <string>
#include <vector>

#include "fullsim/dem/outlet_sink.hpp"

namespace feedflow {

struct DischargeCurve {
  std::vector<double> time;  // [s], one point per sink event (ascending)
  std::vector<double> mass;  // [kg] cumulative
};
// From the sink's events (every particle it took, with its time and mass).
DischargeCurve discharge_curve(const std::vector<SinkEvent>& events);
// The cumulative mass at time t (the events up to and including t) [kg].
double discharged_by(const DischargeCurve& curve, double t);

struct SteadyRateSettings {
  double batch_duration = 0.1;  // [s]
  std::size_t min_batches = 5;  // fewer kept batches: no steady rate
  double confidence = 0.95;
};

struct SteadyRate {
  bool found = false;
  double rate = 0.0;          // [kg/s]
  double low = 0.0, high = 0.0;  // the confidence interval [kg/s]
  double standard_error = 0.0;   // [kg/s]
  double window_start = 0.0, window_end = 0.0;  // [s]
  std::size_t batches = 0;       // kept
  double confidence = 0.95;
  std::string describe() const;  // "0.123 kg/s (95 % CI 0.118-0.128 kg/s) over 1.2-3.4 s, 22 batches"
};

// From a cumulative mass sampled at times `t` (ascending; e.g. the time series of a run),
// starting at `from` (the opening time). Not found when fewer than min_batches remain.
SteadyRate steady_discharge_rate(const std::vector<double>& t, const std::vector<double>& mass,
                                 double from, const SteadyRateSettings& settings = {});

// "Arched": nothing has left for `quiet_time` and the kinetic energy is below that of the
// remaining mass moving at `speed` (flow has clearly stopped, not a pause between surges).
struct ArchCriterion {
  double quiet_time = 0.5;  // [s]
  double speed = 0.01;      // [m/s]
};
enum class DischargeState { flowing, arched, emptied };
const char* to_string(DischargeState state);
// `last_discharge`: the time of the latest sink event (or the opening time when none yet);
// `mass_left`: the mass in the domain above the outlet [kg]; `particles_left` how many.
DischargeState discharge_state(double now, double last_discharge, double kinetic_energy,
                               double mass_left, std::size_t particles_left,
                               const ArchCriterion& criterion = {});

}  // namespace feedflow
