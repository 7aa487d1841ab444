#include "fullsim/dem/scene/speed_profile.hpp"

#include <algorithm>
#include <cmath>

namespace feedflow {

SpeedProfile speed_profile(const BedView& bed, double z, double band, double bin_width,
                           ProfileOffset offset) {
  const ParticleStore& p = bed.store();
  auto in_line = [&](std::size_t i) { return std::abs(p.position[i].z() - z) <= band; };
  auto bin_of = [&](std::size_t i) {
    const Vec3& x = p.position[i];
    const double d = offset == ProfileOffset::across_x ? std::abs(x.x()) : std::hypot(x.x(), x.y());
    return static_cast<std::size_t>(d / bin_width);
  };
  double last = -1.0;  // the outermost bin with a particle, of every rank
  for (std::size_t i = 0; i < bed.own(); ++i)
    if (in_line(i)) last = std::max(last, static_cast<double>(bin_of(i)));
  last = bed.max(last);
  SpeedProfile line;
  if (last < 0.0) return line;
  const auto bins = static_cast<std::size_t>(last) + 1;
  std::vector<double> tally(2 * bins, 0.0);  // per bin: speed sum, then count
  for (std::size_t i = 0; i < bed.own(); ++i) {
    if (!in_line(i)) continue;
    const std::size_t b = bin_of(i);
    tally[2 * b] += p.velocity[i].norm();
    tally[2 * b + 1] += 1.0;
  }
  bed.sum(tally);
  for (std::size_t b = 0; b < bins; ++b) {
    if (tally[2 * b + 1] == 0.0) continue;
    line.offset.push_back((static_cast<double>(b) + 0.5) * bin_width);
    line.speed.push_back(tally[2 * b] / tally[2 * b + 1]);
  }
  return line;
}

}  // namespace feedflow
