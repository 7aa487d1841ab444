#pragma once
// The particles of a run shared among ranks in one store: every rank's own particles, in rank
// order, each whole (particle_record.hpp). On the first rank for snapshots; on every rank for
// what a scene measures.
#include <cstddef>
#include <functional>

#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/ranks/dem_ranks.hpp"

namespace feedflow {

// `owned`: this rank's own particles, the first slots of `p` (ghosts behind are left out).
// Collective; the first rank gets every particle, the others an empty store.
ParticleStore gather_particles(const ParticleStore& p, std::size_t owned, const DemRanks& ranks);

// As gather_particles, every rank getting every particle.
ParticleStore all_gather_particles(const ParticleStore& p, std::size_t owned,
                                   const DemRanks& ranks);

// As all_gather_particles, of the own particles whose slot `select` accepts.
ParticleStore all_gather_particles(const ParticleStore& p, std::size_t owned, const DemRanks& ranks,
                                   const std::function<bool(std::size_t)>& select);

}  // namespace feedflow
