#pragma once
// The particle speeds along a horizontal line across a hopper slab, as the flow-pattern line of
// fullsim/common/flow_pattern_measurement.hpp: the particles whose centres lie within `band`
// of the height `z`, folded about the centre line x = 0 (both walls), averaged in bins of
// `bin_width` from the centre outwards; empty bins are left out.
#include "fullsim/common/flow_pattern_measurement.hpp"
#include "fullsim/dem/particle_store.hpp"

namespace feedflow {

SpeedProfile speed_profile(const ParticleStore& particles, double z, double band, double bin_width);

}  // namespace feedflow
