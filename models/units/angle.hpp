#pragma once
// Angle and rotation-speed units in SI (rad, rad/s), for code that states a value in degrees or
// revolutions per minute: `30 * kDegree`, `20 * kRpm`. The case-file parser uses the same
// constants, so a value written in code and one read from "30 deg" are the same double.
#include <numbers>

namespace feedflow {

inline constexpr double kDegree = std::numbers::pi / 180.0;    // one degree [rad]
inline constexpr double kRpm = 2.0 * std::numbers::pi / 60.0;  // one revolution per minute [rad/s]

// An angle in degrees, for messages and outputs: radians * 180 / pi, in that order.
constexpr double in_degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
// A rotation speed in revolutions per minute, for messages.
constexpr double in_rpm(double radians_per_second) { return radians_per_second / kRpm; }

}  // namespace feedflow
