#pragma once
// A hopper on the continuum rung (L2): a wedge as a plane-strain half slice (or the full-width
// section, [cel] hopper_section), a cone axisymmetric about its axis; filled and settled under
// gravity, then the gate removed;
// sampled every 10 ms (discharged mass, mass in the hopper, kinetic energy, scaled to the slot
// length); measured: q_m over the steady window from the outflow ledger, arching, the flow
// pattern from the wall-to-centre speed ratio.
#include <memory>

#include "designer/simulate/scene_adapter.hpp"

namespace feedflow {

// The fewest cells across the half outlet that resolve a hopper's discharge. `feedflow bench`
// measured the pilot hopper at W = 60 mm (tests/benchmarks/RECORD.md): 1.5 cells (20 mm) read
// "arched" for a hopper that flows; 3, 6 and 12 cells give rates 19 %, 11 % and 7 % above the
// Richardson reference. A coarser cell size is refused, not answered.
inline constexpr double kMinimumCellsAcrossHalfOutlet = 3.0;
// Without [cel] cell_size: 10 mm, or finer where the outlet needs it.
double default_hopper_cell_size(double outlet_width);

std::unique_ptr<SceneAdapter> cel_hopper_adapter(const SimulationRequest& request);

}  // namespace feedflow
