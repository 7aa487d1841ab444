#include "fullsim/dem/ranks/gathered_particles.hpp"

#include <vector>

#include "fullsim/dem/ranks/particle_record.hpp"

namespace feedflow {
namespace {

std::vector<double> own_records(const ParticleStore& p, std::size_t owned,
                                const std::function<bool(std::size_t)>& select = {}) {
  std::vector<double> mine;
  for (std::size_t k = 0; k < owned; ++k)
    if (!select || select(k)) put_particle(mine, p, k);
  return mine;
}

ParticleStore store_of(const std::vector<std::vector<double>>& records, const ParticleStore& like) {
  ParticleStore all;
  all.set_wall_history_stride(like.wall_history_stride());
  for (const std::vector<double>& from : records) {
    const double* q = from.data();
    const double* end = q + from.size();
    while (q < end) take_particle(q, all);
  }
  return all;
}

}  // namespace

ParticleStore gather_particles(const ParticleStore& p, std::size_t owned, const DemRanks& ranks) {
  return store_of(ranks.gather(own_records(p, owned)), p);
}

ParticleStore all_gather_particles(const ParticleStore& p, std::size_t owned,
                                   const DemRanks& ranks) {
  return store_of(ranks.all_gather(own_records(p, owned)), p);
}

ParticleStore all_gather_particles(const ParticleStore& p, std::size_t owned, const DemRanks& ranks,
                                   const std::function<bool(std::size_t)>& select) {
  return store_of(ranks.all_gather(own_records(p, owned, select)), p);
}

}  // namespace feedflow
