#pragma once
// The particle speeds along a horizontal line across a hopper slab, as the flow-pattern line of
// fullsim/common/flow_pattern_measurement.hpp: the particles whose centres lie within `band`
// of the height `z`, folded about the centre line x = 0 (both walls), averaged in bins of
// `bin_width` from the centre outwards; empty bins are left out. Of every rank's particles
// (collective on a shared run).
#include "fullsim/common/flow_pattern_measurement.hpp"
#include "fullsim/dem/bed_view.hpp"

namespace feedflow {

// How far a particle is from the centre: |x| (a wedge, both walls folded together) or its
// distance from the z axis (a cone).
enum class ProfileOffset { across_x, from_axis };

SpeedProfile speed_profile(const BedView& bed, double z, double band, double bin_width,
                           ProfileOffset offset = ProfileOffset::across_x);

}  // namespace feedflow
