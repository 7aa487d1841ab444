#pragma once
// The deposit left on a ramp once the flow has stopped, measured as the seed's DEM did
// (data.md 3: "h_stop = max particle height along the ramp"): the ramp is cut into bins along
// the slope and each bin's height is the highest particle top (centre + radius) above the ramp
// surface; h_stop at mid-ramp as every rung measures it (fullsim/common/deposit_measurement.hpp:
// the mean of the bins within 5 % of the ramp length of mid-ramp, its band their range).
#include <vector>

#include "fullsim/common/deposit_measurement.hpp"
#include "fullsim/dem/bed_view.hpp"

namespace feedflow {

struct DepositProfile {
  std::vector<double> x;       // bin centres along the slope from the gate [m]
  std::vector<double> height;  // highest particle top above the ramp surface [m] (0: empty bin)
  DepositThickness mid_ramp;    // h_stop at mid-ramp with its band [m]
  double front = 0.0;          // farthest bin with a particle in it [m]
};

// Positions in the ramp frame: x along the slope from the gate, z normal to the ramp; the ramp
// surface at z = `surface`. Bins of `bin_width` over [0, ramp_length]. Of every rank's particles
// (collective on a shared run).
DepositProfile measure_deposit(const BedView& bed, double ramp_length, double surface,
                               double bin_width);

// True once the mean kinetic energy per particle is below a thousandth of lifting one by its
// diameter against `g` (a particle of the bed moving at about 1 % of sqrt(g d)): the flow has
// clearly stopped. An empty bed is at rest. Collective on a shared run.
bool bed_at_rest(const BedView& bed, double diameter, double g);

}  // namespace feedflow
