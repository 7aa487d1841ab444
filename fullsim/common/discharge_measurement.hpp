#pragma once
// The discharge of a hopper, bin or silo measured on a run's time series, the same for every
// rung (the DEM's sink and the CEL outflow ledger are both sampled into a cumulative
// discharged mass against time): the steady mass flow rate with its confidence interval, and
// whether the discharge flows, has arched or has emptied.
//
// Steady window: the cumulative mass is cut into batches of equal duration and each batch's
// rate dm/dt taken. The start-up transient and the emptying tail are dropped by the MSER rule
// (White 1997: keep the truncation that minimises the squared standard error of the mean of
// what is left, var / (n - d)^2), taken over both ends at once (each at most half the
// batches). The rate is the mean of the kept batch rates (= the secant slope of the window);
// its interval is the batch-means t interval (GSL t quantile). Batch means rather than the
// regression error of m(t): the residuals of a cumulative curve are correlated and would
// understate the error.
//
// Arched: the discharge has stopped. Over the last `quiet_time` no sample interval carried
// more than a trickle (a share of the outlet's scale rate rho_b W sqrt(g W), per metre of slot
// or for the whole outlet; a continuum always creeps, and a particle or two may still drop) and
// the kinetic energy is below that of the mass left moving at `speed` (not a pause between
// surges). Emptied: less than `empty_fraction` of the fill is left.
#include <cstddef>
#include <string>
#include <vector>

namespace feedflow {

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

struct ArchCriterion {
  double quiet_time = 0.5;      // [s]
  double speed = 0.01;          // [m/s]
  double trickle_share = 0.02;  // of the scale rate rho_b W sqrt(g W)
  double empty_fraction = 1e-3; // of the fill
};

// The outlet's scale rate rho_b W sqrt(g W) [kg/s per metre of slot, x the slot length (or the
// slab depth) for a rate in kg/s].
double outlet_scale_rate(double bulk_density, double outlet_width);

enum class DischargeState { flowing, arched, emptied };
const char* to_string(DischargeState state);

// The end of the last sample interval after `from` that carried more than `trickle_rate`
// [kg/s], or `from` when none did.
double last_discharge_time(const std::vector<double>& t, const std::vector<double>& mass,
                           double from, double trickle_rate);
// `last_discharge`: last_discharge_time() (or the opening time when nothing left yet);
// `mass_left`: the mass in the domain above the outlet [kg]; `fraction_left` of the fill.
DischargeState discharge_state(double now, double last_discharge, double kinetic_energy,
                               double mass_left, double fraction_left,
                               const ArchCriterion& criterion = {});

}  // namespace feedflow
