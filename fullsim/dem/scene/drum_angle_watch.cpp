#include "fullsim/dem/scene/drum_angle_watch.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace feedflow {

std::vector<AngleSample> DrumAngleWatch::angles() const {
  std::vector<AngleSample> a;
  a.reserve(samples_.size());
  for (const auto& x : samples_) a.push_back({x.time, x.angle, x.valid});
  return a;
}

bool DrumAngleWatch::converged() const { return angle_converged(angles(), windows_); }

std::optional<DrumSteadyResult> DrumAngleWatch::steady() const {
  if (samples_.empty()) return std::nullopt;
  const SteadyAngle a = steady_angle(angles(), windows_);
  DrumSteadyResult r;
  r.from = a.from;
  r.to = a.to;
  for (const auto& x : samples_) {
    if (!(x.time > r.from)) continue;
    r.state.airborne_fraction += x.state.airborne_fraction;
    r.state.over_top_fraction += x.state.over_top_fraction;
    r.state.solid_body_fraction += x.state.solid_body_fraction;
    r.state.shell_speed_ratio += x.state.shell_speed_ratio;
    r.state.particles += x.state.particles;
    ++r.samples;
  }
  if (r.samples == 0) return std::nullopt;
  const double n = static_cast<double>(r.samples);
  r.state.airborne_fraction /= n;
  r.state.over_top_fraction /= n;
  r.state.solid_body_fraction /= n;
  r.state.shell_speed_ratio /= n;
  r.state.particles /= n;
  const std::size_t valid = a.valid;
  if (a.found) {
    r.angle = a.angle;
    r.angle_sd = a.sd;
    r.state.angle_swing = a.swing;
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
