#pragma once
// The DEM settings of a case for `feedflow simulate`: the material's Table 2 sets, the normal
// law chosen by [dem] normal_law (+ history + cdt, the seed's composition), the time step of [dem] time_step (below the stable one:
// warned; above it: refused by the engine unless forced).
#include "designer/case/case.hpp"
#include "fullsim/dem/dem_engine.hpp"

namespace feedflow {

// Throws InputError naming the material when it has no [dem] parameters.
DemSettings dem_case_settings(const Case& c);

// Throws InputError naming dem.slab_depth when a periodic slab is thinner than two neighbour
// cutoffs of the settings' particles (a particle would meet its own image).
void require_slab_depth(const Case& c, const DemSettings& settings, double slab_depth);

}  // namespace feedflow
