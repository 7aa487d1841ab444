#pragma once
// The seed's inclined-plane test as an L1 problem: a storage bin at the upper end of the ramp,
// a gate lifted to `gate_opening`, the ramp below, material falling off its lower end.
//
// Modelling choices (stated, not hidden):
// - the bin floor is the ramp itself, continued upslope by bin_length (the seed's bin stands
//   on the upper end of the ramp), so x runs from -bin_length (back wall) to chute.length
//   (free end) with the gate at x = 0;
// - the fill is a column of fill_height (taken normal to the ramp) over the bin length, at rest;
//   shallow-flow theory is stretched in a bin as deep as it is long: read the bin as a reservoir
//   that feeds the gate, not as a resolved bin flow;
// - the gate is a wall from gate_opening upwards: at the gate face both reconstructed
//   thicknesses are capped at the opening, the wall takes the pressure of the rest (a sluice
//   gate in hydrostatic reconstruction form), and mass passes only below it;
// - the stopping thickness is read at mid-ramp (chute.length/2), where the seed measured it.
#include "models/chute/ramp_flow_solver.hpp"
#include "models/equipment/chute.hpp"

namespace feedflow {

struct ChuteReleaseOptions {
  double cell_size = 5e-3;      // [m]
  double earth_pressure = 1.0;  // k [-]
  RampFlowSettings settings;    // ramp_begin and probe_position are filled in
};

// Throws std::invalid_argument for a chute without positive length, bin length, fill height
// and gate opening, or an angle outside (0, 90) degrees.
RampFlowResult run_chute_release(const Chute& chute, const PouliquenLaw& friction,
                                 const ChuteReleaseOptions& options = {});

}  // namespace feedflow
