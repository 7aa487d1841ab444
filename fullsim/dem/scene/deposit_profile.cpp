#include "fullsim/dem/scene/deposit_profile.hpp"

#include <algorithm>
#include <cmath>

namespace feedflow {

DepositProfile measure_deposit(const BedView& bed, double ramp_length, double surface,
                               double bin_width) {
  const ParticleStore& p = bed.store();
  DepositProfile d;
  const auto bins = static_cast<std::size_t>(std::ceil(ramp_length / bin_width));
  d.x.resize(bins);
  d.height.assign(bins, 0.0);
  for (std::size_t b = 0; b < bins; ++b) d.x[b] = (static_cast<double>(b) + 0.5) * bin_width;
  for (std::size_t i = 0; i < bed.own(); ++i) {
    const double x = p.position[i].x();
    if (x < 0.0 || x >= ramp_length) continue;
    const auto b = std::min(bins - 1, static_cast<std::size_t>(x / bin_width));
    d.height[b] = std::max(d.height[b], p.position[i].z() + p.radius[i] - surface);
    d.front = std::max(d.front, d.x[b]);
  }
  bed.max(d.height);
  d.front = bed.max(d.front);
  d.mid_ramp = mid_ramp_thickness(d.x, d.height, ramp_length);
  return d;
}

bool bed_at_rest(const BedView& bed, double diameter, double g) {
  const double mass = bed.total_mass();
  return mass == 0.0 || bed.kinetic_energy() < 1e-3 * mass * g * diameter;
}

}  // namespace feedflow
