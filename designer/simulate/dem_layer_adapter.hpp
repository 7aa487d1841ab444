#pragma once
// A chute's stopping layer on the particle rung (L3), when the case asks for one ([dem]
// stopping_layer = thickness): a periodic layer of that thickness on the seed's saw-tooth ramp
// (fullsim/dem/scene/stopping_layer.hpp), rained in and trimmed, set flowing on a 60 deg ramp,
// then tilted to the chute's angle; sampled every 20 ms (mean speed down the slope, kinetic
// energy, thickness); stopped once it is at rest (after 0.1 s), runs away (its mean speed past
// 1.5 times the launch's: it flows on), or flows steadily from 4 s after the tilt on (no longer
// slowing), else at 10 s after the tilt ([dem] end_time instead; --time: only its end counts).
// Measured: whether it came to rest, and its thickness, speed and time. A thickness that rests is
// at most h_stop at the angle, one that flows above it, so `design --verify dem` brackets h_stop by
// a bisection of such runs.
#include <memory>

#include "designer/simulate/scene_adapter.hpp"
#include "fullsim/dem/scene/stopping_layer.hpp"

namespace feedflow {

// [s] after the tilt: from the cap on, a layer that no longer slows ends as flowing; one still
// slowing runs on to the limit (a layer near h_stop slows for long before it stops: measured at
// 35 deg, 43.7 mm rested 2.2 s after the tilt, 54.4 mm held its speed for 2 s, then slowed).
constexpr double kStoppingLayerRunCap = 4.0;
constexpr double kStoppingLayerRunLimit = 10.0;

// The layer the case asks for with `settings` (dem_case_settings): the chute's angle, [dem]
// stopping_layer, slab_depth and random_seed. Throws InputError naming the key for a layer
// thinner than a sphere, a slab too thin, or slab faces other than periodic.
StoppingLayerSpec stopping_layer_spec(const Case& c, const DemSettings& settings);

std::unique_ptr<SceneAdapter> dem_layer_adapter(const SimulationRequest& request);

}  // namespace feedflow
