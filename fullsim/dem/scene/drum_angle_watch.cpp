#include "fullsim/dem/scene/drum_angle_watch.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace feedflow {

namespace {

double mean_angle(const std::vector<DrumSample>& s, double from, double to, std::size_t& count) {
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

bool DrumAngleWatch::converged() const {
  if (samples_.empty()) return false;
  const double t = samples_.back().time;
  if (t < spin_up_ + 2.0 * window_) return false;
  std::size_t a = 0, b = 0;
  const double last = mean_angle(samples_, t - window_, t, a);
  const double before = mean_angle(samples_, t - 2.0 * window_, t - window_, b);
  if (a < 3 && b < 3) return true;  // no free surface: the bed turns with the shell
  return a >= 3 && b >= 3 && std::abs(last - before) < tolerance_;
}

std::optional<DrumSteadyResult> DrumAngleWatch::steady() const {
  if (samples_.empty()) return std::nullopt;
  DrumSteadyResult r;
  r.to = samples_.back().time;
  r.from = std::max(spin_up_, r.to - 2.0 * window_);
  double lo = 1e300, hi = -1e300, sum = 0.0, sum2 = 0.0;
  for (const auto& x : samples_) {
    if (!(x.time > r.from)) continue;
    r.state.airborne_fraction += x.state.airborne_fraction;
    r.state.over_top_fraction += x.state.over_top_fraction;
    r.state.solid_body_fraction += x.state.solid_body_fraction;
    r.state.shell_speed_ratio += x.state.shell_speed_ratio;
    r.state.particles += x.state.particles;
    ++r.samples;
    if (!x.valid) continue;
    sum += x.angle;
    sum2 += x.angle * x.angle;
    lo = std::min(lo, x.angle);
    hi = std::max(hi, x.angle);
  }
  if (r.samples == 0) return std::nullopt;
  const double n = static_cast<double>(r.samples);
  r.state.airborne_fraction /= n;
  r.state.over_top_fraction /= n;
  r.state.solid_body_fraction /= n;
  r.state.shell_speed_ratio /= n;
  r.state.particles /= n;
  std::size_t valid = 0;
  for (const auto& x : samples_) valid += x.valid && x.time > r.from;
  if (valid > 0) {
    const double m = sum / static_cast<double>(valid);
    r.angle = m;
    r.angle_sd = std::sqrt(std::max(0.0, sum2 / static_cast<double>(valid) - m * m));
    r.state.angle_swing = hi - lo;
  }
  // The time-averaged profile: the columns' mean heights (column centres are fixed).
  std::map<long, std::pair<double, int>> columns;
  for (const auto& x : samples_)
    if (x.time > r.from)
      for (const auto& p : x.surface) {
        auto& c = columns[std::lround(p.x * 1e6)];
        c.first += p.z;
        ++c.second;
      }
  const double least = 0.5 * static_cast<double>(valid);
  for (const auto& [key, c] : columns)
    if (c.second >= least) r.mean_surface.push_back({static_cast<double>(key) * 1e-6, c.first / c.second});
  r.state.surface_bulge = fit_drum_surface(r.mean_surface, radius_).bulge;
  r.low = r.angle - 2.0 * r.angle_sd;
  r.high = r.angle + 2.0 * r.angle_sd;
  return r;
}

}  // namespace feedflow
