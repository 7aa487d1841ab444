#include "fullsim/dem/scene/speed_profile.hpp"

#include <cmath>
#include <map>

namespace feedflow {

SpeedProfile speed_profile(const ParticleStore& p, double z, double band, double bin_width) {
  std::map<long, std::pair<double, int>> bins;  // bin index -> speed sum, count
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (std::abs(p.position[i].z() - z) > band) continue;
    auto& b = bins[static_cast<long>(std::abs(p.position[i].x()) / bin_width)];
    b.first += p.velocity[i].norm();
    ++b.second;
  }
  SpeedProfile line;
  for (const auto& [k, b] : bins) {
    line.offset.push_back((static_cast<double>(k) + 0.5) * bin_width);
    line.speed.push_back(b.first / b.second);
  }
  return line;
}

}  // namespace feedflow
