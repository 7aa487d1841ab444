#include "fullsim/dem/ranks/gathered_particles.hpp"

#include <vector>

#include "fullsim/dem/ranks/particle_record.hpp"

namespace feedflow {

ParticleStore gather_particles(const ParticleStore& p, std::size_t owned, const DemRanks& ranks) {
  std::vector<double> mine;
  for (std::size_t k = 0; k < owned; ++k) put_particle(mine, p, k);
  ParticleStore all;
  all.set_wall_history_stride(p.wall_history_stride());
  for (const std::vector<double>& from : ranks.gather(mine)) {
    const double* q = from.data();
    const double* end = q + from.size();
    while (q < end) take_particle(q, all);
  }
  return all;
}

}  // namespace feedflow
