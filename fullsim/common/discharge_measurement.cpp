#include "fullsim/common/discharge_measurement.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "models/core/gravity.hpp"
#include "models/numerics/mser_truncation.hpp"

namespace feedflow {
namespace {

// Linear interpolation of the sampled cumulative mass.
double mass_at(const std::vector<double>& t, const std::vector<double>& m, double time) {
  auto it = std::lower_bound(t.begin(), t.end(), time);
  if (it == t.begin()) return m.front();
  if (it == t.end()) return m.back();
  const std::size_t k = static_cast<std::size_t>(it - t.begin());
  const double f = (time - t[k - 1]) / (t[k] - t[k - 1]);
  return m[k - 1] + f * (m[k] - m[k - 1]);
}

}  // namespace

std::string SteadyRate::describe() const {
  if (!found) return "no steady window (too few batches)";
  char buf[300];
  std::snprintf(buf, sizeof buf, "%.4g kg/s (%.0f %% CI %.4g-%.4g kg/s) over t = %.3g-%.3g s, %zu batches",
                rate, 100.0 * confidence, low, high, window_start, window_end, batches);
  return buf;
}

SteadyRate steady_discharge_rate(const std::vector<double>& t, const std::vector<double>& mass,
                                 double from, const SteadyRateSettings& s) {
  SteadyRate r;
  if (t.size() < 2 || t.size() != mass.size() || !(s.batch_duration > 0.0)) return r;
  // Begin at the first discharge after `from`: before it the gate or the start-up holds.
  double start = from;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= from && mass[k] > mass_at(t, mass, from)) {
      start = k > 0 ? std::max(from, t[k - 1]) : t[k];
      break;
    }
  const double end = t.back();
  const auto n = static_cast<std::size_t>(std::floor((end - start) / s.batch_duration + 1e-9));
  if (n < s.min_batches) return r;
  std::vector<double> rates(n);
  for (std::size_t b = 0; b < n; ++b) {
    const double a = start + static_cast<double>(b) * s.batch_duration;
    rates[b] = (mass_at(t, mass, a + s.batch_duration) - mass_at(t, mass, a)) / s.batch_duration;
  }
  const auto [front, back] = mser_truncation(rates, s.min_batches);
  const std::vector<double> kept(rates.begin() + static_cast<std::ptrdiff_t>(front),
                                 rates.end() - static_cast<std::ptrdiff_t>(back));
  if (kept.size() < s.min_batches) return r;
  const std::size_t m = kept.size();
  r.found = true;
  r.confidence = s.confidence;
  r.batches = m;
  r.rate = gsl_stats_mean(kept.data(), 1, m);
  r.standard_error = gsl_stats_sd_m(kept.data(), 1, m, r.rate) / std::sqrt(static_cast<double>(m));
  const double q = gsl_cdf_tdist_Pinv(0.5 + 0.5 * s.confidence, static_cast<double>(m - 1));
  r.low = r.rate - q * r.standard_error;
  r.high = r.rate + q * r.standard_error;
  r.window_start = start + static_cast<double>(front) * s.batch_duration;
  r.window_end = r.window_start + static_cast<double>(m) * s.batch_duration;
  return r;
}

const char* to_string(DischargeState state) {
  switch (state) {
    case DischargeState::flowing: return "flowing";
    case DischargeState::arched: return "arched";
    case DischargeState::emptied: return "emptied (no arch)";
  }
  return "flowing";
}

double outlet_scale_rate(double bulk_density, double outlet_width) {
  return bulk_density * outlet_width * std::sqrt(kGravity * outlet_width);
}

double last_discharge_time(const std::vector<double>& t, const std::vector<double>& mass, double from,
                           double trickle_rate) {
  double last = from;
  for (std::size_t k = 1; k < t.size() && k < mass.size(); ++k)
    if (t[k] > from && mass[k] - mass[k - 1] > trickle_rate * (t[k] - t[k - 1])) last = t[k];
  return last;
}

DischargeState discharge_state(double now, double last_discharge, double kinetic_energy,
                               double mass_left, double fraction_left, const ArchCriterion& c) {
  if (fraction_left <= c.empty_fraction) return DischargeState::emptied;
  const bool quiet = now - last_discharge >= c.quiet_time;
  const bool still = kinetic_energy <= 0.5 * mass_left * c.speed * c.speed;
  return quiet && still ? DischargeState::arched : DischargeState::flowing;
}

}  // namespace feedflow
