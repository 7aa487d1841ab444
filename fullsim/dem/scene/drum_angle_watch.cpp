#include "fullsim/dem/scene/drum_angle_watch.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
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

std::string DrumAngleWatch::converged_reason() const {
  return feedflow::converged_reason(angles(), windows_);
}

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
  r.interval = describe_interval(a, windows_);
  r.interval_half_width = interval_half_width(a);
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

namespace {

// The bed state of a sample as a row, in DrumBedState's order.
constexpr std::size_t kStateColumns = 7;
std::array<double, kStateColumns> state_row(const DrumBedState& b) {
  return {b.surface_bulge,       b.angle_swing,       b.airborne_fraction, b.over_top_fraction,
          b.solid_body_fraction, b.shell_speed_ratio, b.particles};
}

}  // namespace

void DrumAngleWatch::save(Hdf5File& file, const std::string& group) const {
  const std::size_t n = samples_.size();
  std::vector<double> time, angle, valid, energy, state, x, z;
  std::vector<std::uint64_t> first{0};
  for (const auto& s : samples_) {
    time.push_back(s.time);
    angle.push_back(s.angle);
    valid.push_back(s.valid ? 1.0 : 0.0);
    energy.push_back(s.kinetic_energy);
    for (double v : state_row(s.state)) state.push_back(v);
    for (const auto& p : s.surface) {
      x.push_back(p.x);
      z.push_back(p.z);
    }
    first.push_back(x.size());
  }
  file.create_group(group);
  file.write(group + "/time", time, {n}, "s");
  file.write(group + "/angle", angle, {n}, "rad");
  file.write(group + "/valid", valid, {n}, "");
  file.write(group + "/kinetic_energy", energy, {n}, "J");
  file.write(group + "/bed_state", state, {n, kStateColumns}, "");
  file.write(group + "/surface_first", first, {n + 1}, "");
  file.write(group + "/surface_x", x, {x.size()}, "m");
  file.write(group + "/surface_z", z, {z.size()}, "m");
}

void DrumAngleWatch::restore(const Hdf5File& file, const std::string& group) {
  const auto time = file.read<double>(group + "/time");
  const std::size_t n = time.size();
  const auto angle = file.read<double>(group + "/angle", {n});
  const auto valid = file.read<double>(group + "/valid", {n});
  const auto energy = file.read<double>(group + "/kinetic_energy", {n});
  const auto state = file.read<double>(group + "/bed_state", {n, kStateColumns});
  const auto first = file.read<std::uint64_t>(group + "/surface_first", {n + 1});
  const auto x = file.read<double>(group + "/surface_x");
  const auto z = file.read<double>(group + "/surface_z", {x.size()});
  samples_.clear();
  for (std::size_t k = 0; k < n; ++k) {
    DrumSample s;
    s.time = time[k];
    s.angle = angle[k];
    s.valid = valid[k] > 0.5;
    s.kinetic_energy = energy[k];
    const double* b = &state[k * kStateColumns];
    s.state = {b[0], b[1], b[2], b[3], b[4], b[5], b[6]};
    if (first[k] > first[k + 1] || first[k + 1] > x.size())
      throw std::runtime_error("drum samples in " + group + ": surface offsets out of order");
    for (std::size_t i = first[k]; i < first[k + 1]; ++i) s.surface.push_back({x[i], z[i]});
    samples_.push_back(std::move(s));
  }
}

}  // namespace feedflow
