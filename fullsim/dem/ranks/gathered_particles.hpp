#pragma once
// The particles of a run shared among ranks in one store on the first rank (for snapshots):
// every rank's own particles, in rank order, each whole (particle_record.hpp).
#include <cstddef>

#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/ranks/dem_ranks.hpp"

namespace feedflow {

// `owned`: this rank's own particles, the first slots of `p` (ghosts behind are left out).
// Collective; the first rank gets every particle, the others an empty store.
ParticleStore gather_particles(const ParticleStore& p, std::size_t owned, const DemRanks& ranks);

}  // namespace feedflow
