#pragma once
// The outlet sink of a run shared among ranks with every rank's books merged: each rank books
// the grains it removed; merged, the removed mass is the sum and the events are in (time, id)
// order, as one rank would have booked them. The discharge a scene reads, and a checkpoint's.
#include "fullsim/dem/outlet_sink.hpp"
#include "fullsim/dem/ranks/dem_ranks.hpp"

namespace feedflow {

// Collective; every rank gets the merged sink.
OutletSink merge_sink_books(const OutletSink& mine, const DemRanks& ranks);

}  // namespace feedflow
