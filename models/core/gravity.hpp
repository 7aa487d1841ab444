#pragma once
// Standard gravity as the reduced models use it (reduced_models.md works with 9.81 m/s^2).
namespace feedflow {
inline constexpr double kGravity = 9.81;  // [m/s^2]
}  // namespace feedflow
