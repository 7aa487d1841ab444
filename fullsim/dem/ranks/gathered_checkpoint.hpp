#pragma once
// The checkpoint of a run shared among ranks, made what one rank's would be: every rank's own
// particles (in rank order), the contacts listed under them with their history (partners
// found by id among the gathered particles), the positions of the last rebuild, and the
// outlet sink's books merged. It restarts on any number of ranks: one takes it as is, several
// share it out again (dem_engine.cpp).
#include <cstddef>

#include "fullsim/dem/dem_checkpoint.hpp"
#include "fullsim/dem/ranks/dem_ranks.hpp"

namespace feedflow {

// `mine` is this rank's checkpoint: its store (own particles in the first `owned` slots, ghost
// copies behind), its list (rows for the own particles), its sink with its own books.
// Collective; every rank gets the whole checkpoint (the first writes it; a scene that rebuilds
// its engine from it, as the drum does to start turning, does so on every rank).
DemCheckpoint gather_checkpoint(DemCheckpoint mine, std::size_t owned, const DemRanks& ranks);

}  // namespace feedflow
