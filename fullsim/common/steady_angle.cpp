#include "fullsim/common/steady_angle.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "models/numerics/mser_truncation.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

double mean_angle(const std::vector<AngleSample>& s, double from, double to, std::size_t& count) {
  double sum = 0.0;
  count = 0;
  for (const auto& x : s)
    if (x.valid && x.time > from && x.time <= to) {
      sum += x.angle;
      ++count;
    }
  return count ? sum / static_cast<double>(count) : 0.0;
}

// Mean, SD, range and counts of the samples in (from, to].
void describe_window(const std::vector<AngleSample>& samples, SteadyAngle& r) {
  double lo = 1e300, hi = -1e300, sum = 0.0, sum2 = 0.0;
  for (const auto& x : samples) {
    if (!(x.time > r.from && x.time <= r.to)) continue;
    ++r.samples;
    if (!x.valid) continue;
    ++r.valid;
    sum += x.angle;
    sum2 += x.angle * x.angle;
    lo = std::min(lo, x.angle);
    hi = std::max(hi, x.angle);
  }
  if (r.valid == 0) return;
  r.found = true;
  const double n = static_cast<double>(r.valid);
  r.angle = sum / n;
  r.sd = std::sqrt(std::max(0.0, sum2 / n - r.angle * r.angle));
  r.swing = hi - lo;
  r.low = r.angle - 2.0 * r.sd;
  r.high = r.angle + 2.0 * r.sd;
  r.ci_low = r.low;
  r.ci_high = r.high;
}

}  // namespace

AngleWindows drum_angle_windows(double speed) {
  const double period = speed > 0.0 ? 2.0 * std::numbers::pi / speed : 1e9;
  return {std::max(0.5, 0.15 * period), std::max(0.5, 0.1 * period), std::numbers::pi / 180.0, 5,
          0.95};
}

bool angle_converged(const std::vector<AngleSample>& samples, const AngleWindows& w) {
  if (samples.empty()) return false;
  const double t = samples.back().time;
  if (t < w.spin_up + 2.0 * w.window) return false;
  std::size_t a = 0, b = 0;
  mean_angle(samples, t - w.window, t, a);
  mean_angle(samples, t - 2.0 * w.window, t - w.window, b);
  if (a < 3 && b < 3) return true;  // no free surface: the bed turns with the shell
  return steady_angle(samples, w).converged;
}

SteadyAngle steady_angle(const std::vector<AngleSample>& samples, const AngleWindows& w) {
  SteadyAngle r;
  if (samples.empty()) return r;
  // Batch means of the valid samples, in whole batches after the spin-up.
  const auto whole = static_cast<std::size_t>(
      std::max(0.0, std::floor((samples.back().time - w.spin_up) / w.window + 1e-9)));
  std::vector<double> means;
  std::vector<std::size_t>
      first;  // the batch index of each mean (batches without a surface have none)
  for (std::size_t k = 0; k < whole; ++k) {
    std::size_t count = 0;
    const double from = w.spin_up + static_cast<double>(k) * w.window;
    const double m = mean_angle(samples, from, from + w.window, count);
    if (count == 0) continue;
    means.push_back(m);
    first.push_back(k);
  }
  if (means.size() < 2) {  // too short to tell a transient: whatever follows the spin-up
    r.from = w.spin_up;
    r.to = samples.back().time;
    describe_window(samples, r);
    return r;
  }
  const std::size_t front = mser_truncation(means, w.min_batches, MserEnds::front).first;
  const std::vector<double> kept(means.begin() + static_cast<std::ptrdiff_t>(front), means.end());
  r.from = w.spin_up + static_cast<double>(first[front]) * w.window;
  r.to = w.spin_up + static_cast<double>(whole) * w.window;
  describe_window(samples, r);
  r.batches = kept.size();
  r.dropped = front;
  double mean = 0.0, var = 0.0;
  for (double m : kept) mean += m;
  mean /= static_cast<double>(kept.size());
  for (double m : kept) var += (m - mean) * (m - mean);
  var /= static_cast<double>(kept.size() - 1);
  const double half =
      gsl_cdf_tdist_Pinv(0.5 + 0.5 * w.confidence, static_cast<double>(kept.size() - 1)) *
      std::sqrt(var / static_cast<double>(kept.size()));
  r.ci_low = r.angle - half;
  r.ci_high = r.angle + half;
  r.converged = kept.size() >= w.min_batches && half <= w.tolerance;
  return r;
}

std::optional<double> interval_half_width(const SteadyAngle& a) {
  if (a.batches < 2) return std::nullopt;
  return 0.5 * (a.ci_high - a.ci_low);
}

std::string describe_interval(const SteadyAngle& a, const AngleWindows& w) {
  const auto half = interval_half_width(a);
  if (!half) return "no interval of the mean (fewer than two batches after the spin-up)";
  return format_number(100.0 * w.confidence, 3) + " % interval of the mean +-" +
         format_quantity(*half, "deg", 2) + " over " + std::to_string(a.batches) + " batches of " +
         format_quantity(w.window, "s", 2) + ", " + std::to_string(a.dropped) +
         " of the start-up transient dropped";
}

std::string converged_reason(const std::vector<AngleSample>& samples, const AngleWindows& w) {
  if (!angle_converged(samples, w)) return {};
  const SteadyAngle a = steady_angle(samples, w);
  if (!a.converged) return "converged: no free surface (the bed turns with the shell)";
  return "converged: " + describe_interval(a, w) + ", within " +
         format_quantity(w.tolerance, "deg", 2);
}

}  // namespace feedflow
