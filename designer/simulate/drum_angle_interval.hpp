#pragma once
// The drum's angle is a time average: beside it in the results, the half-width of its mean's
// 95 % interval (Student t over the kept batch means, fullsim/common/steady_angle.hpp), a result
// of its own because the angle's band is 2 SD of the sampled angle (where one snapshot may lie),
// far wider than the mean's uncertainty. The bench takes it as the run's statistical error, and
// verification judges the mean by it.
#include <optional>

#include "models/core/design_record.hpp"

namespace feedflow {

// Adds the entry (interval_key("dynamic_angle_of_repose")) for a half-width `half_width` [rad];
// nothing without an interval (fewer than two batches).
void add_angle_interval(Estimates& results, std::optional<double> half_width, Rung rung);

}  // namespace feedflow
