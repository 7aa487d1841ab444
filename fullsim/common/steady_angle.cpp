#include "fullsim/common/steady_angle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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

}  // namespace

AngleWindows drum_angle_windows(double speed) {
  const double period = speed > 0.0 ? 2.0 * std::numbers::pi / speed : 1e9;
  return {std::max(0.5, 0.15 * period), std::max(0.5, 0.1 * period), std::numbers::pi / 180.0};
}

bool angle_converged(const std::vector<AngleSample>& samples, const AngleWindows& w) {
  if (samples.empty()) return false;
  const double t = samples.back().time;
  if (t < w.spin_up + 2.0 * w.window) return false;
  std::size_t a = 0, b = 0;
  const double last = mean_angle(samples, t - w.window, t, a);
  const double before = mean_angle(samples, t - 2.0 * w.window, t - w.window, b);
  if (a < 3 && b < 3) return true;  // no free surface: the bed turns with the shell
  return a >= 3 && b >= 3 && std::abs(last - before) < w.tolerance;
}

SteadyAngle steady_angle(const std::vector<AngleSample>& samples, const AngleWindows& w) {
  SteadyAngle r;
  if (samples.empty()) return r;
  r.to = samples.back().time;
  r.from = std::max(w.spin_up, r.to - 2.0 * w.window);
  double lo = 1e300, hi = -1e300, sum = 0.0, sum2 = 0.0;
  for (const auto& x : samples) {
    if (!(x.time > r.from)) continue;
    ++r.samples;
    if (!x.valid) continue;
    ++r.valid;
    sum += x.angle;
    sum2 += x.angle * x.angle;
    lo = std::min(lo, x.angle);
    hi = std::max(hi, x.angle);
  }
  if (r.valid == 0) return r;
  r.found = true;
  const double n = static_cast<double>(r.valid);
  r.angle = sum / n;
  r.sd = std::sqrt(std::max(0.0, sum2 / n - r.angle * r.angle));
  r.swing = hi - lo;
  r.low = r.angle - 2.0 * r.sd;
  r.high = r.angle + 2.0 * r.sd;
  return r;
}

}  // namespace feedflow
