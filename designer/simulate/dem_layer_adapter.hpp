#pragma once
// A chute's stopping layer on the particle rung (L3), when the case asks for one ([dem]
// stopping_layer = thickness): a periodic layer of that thickness on the seed's saw-tooth ramp
// (fullsim/dem/scene/stopping_layer.hpp), rained in and trimmed, set flowing on a 60 deg ramp,
// then tilted to the chute's angle; sampled every 20 ms (mean speed down the slope, kinetic
// energy, thickness); stopped once it is at rest (after 0.1 s) or runs away (its mean speed past
// 1.5 times the launch's: it flows on), else run for 4 s after the tilt (--time or [dem]
// end_time: then only the end counts). Measured: whether it came to rest, and its thickness,
// speed and time. A thickness that rests is at most h_stop at the angle, one that flows above it,
// so `design --verify dem` brackets h_stop by a bisection of such runs.
#include <memory>

#include "designer/simulate/scene_adapter.hpp"
#include "fullsim/dem/scene/stopping_layer.hpp"

namespace feedflow {

// [s] after the tilt, the longest a layer runs unless told: near h_stop a layer slows for long
// before it stops (measured 1.8 s at 37 deg, a 25 mm layer of the seed's spheres).
constexpr double kStoppingLayerRunCap = 4.0;

// The layer the case asks for with `settings` (dem_case_settings): the chute's angle, [dem]
// stopping_layer, slab_depth and random_seed. Throws InputError naming the key for a layer
// thinner than a sphere, a slab too thin, or slab faces other than periodic.
StoppingLayerSpec stopping_layer_spec(const Case& c, const DemSettings& settings);

std::unique_ptr<SceneAdapter> dem_layer_adapter(const SimulationRequest& request);

}  // namespace feedflow
