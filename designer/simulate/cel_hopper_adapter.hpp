#pragma once
// The wedge hopper on the continuum rung (L2): a plane-strain half slice (or the full-width
// section, [cel] hopper_section) filled and settled under gravity, then the gate removed;
// sampled every 10 ms (discharged mass, mass in the hopper, kinetic energy, scaled to the slot
// length); measured: q_m over the steady window from the outflow ledger, arching, the flow
// pattern from the wall-to-centre speed ratio.
#include <memory>

#include "designer/simulate/scene_adapter.hpp"

namespace feedflow {

std::unique_ptr<SceneAdapter> cel_hopper_adapter(const SimulationRequest& request);

}  // namespace feedflow
