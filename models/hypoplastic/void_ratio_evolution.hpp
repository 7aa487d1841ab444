#pragma once
// Void-ratio evolution de/dt = (1 + e) tr D (seed Eq. 3b; models.md 1.1) and the INL clamp
// (models.md 1.5 item 4).
#include <algorithm>
#include <cmath>

namespace feedflow {

inline double void_ratio_rate(double void_ratio, double trace_stretching) {
  return (1.0 + void_ratio) * trace_stretching;
}

// Exact solution over dt for constant tr D: 1 + e = (1 + e0) exp(tr D dt) (mass balance).
inline double evolve_void_ratio(double void_ratio, double trace_stretching, double dt) {
  return (1.0 + void_ratio) * std::exp(trace_stretching * dt) - 1.0;
}

// [1.001 e_d, 0.999 e_i] at the pressure whose Bauer factor exp(-(3p/h_s)^n) is given.
inline double clamp_void_ratio(double void_ratio, double e_d0, double e_i0, double bauer_factor) {
  return std::clamp(void_ratio, 1.001 * e_d0 * bauer_factor, 0.999 * e_i0 * bauer_factor);
}

}  // namespace feedflow
