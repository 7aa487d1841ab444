#pragma once
// Pouliquen's (theta2, L) from two measured stopping thicknesses at two inclinations, with
// theta1 fixed (reduced_models.md section 3 item 5): r = h1/h2 = [(T2 - t1)(t2 - T1)] /
// [(T2 - t2)(t1 - T1)] is linear in T2 = tan theta2; then L = h1 (t1 - T1)/(T2 - t1).
#include "models/chute/pouliquen_law.hpp"

namespace feedflow {

struct StopMeasurement {
  double angle = 0.0;      // inclination [rad]
  double thickness = 0.0;  // measured h_stop [m]
};

// Returns a law with the given theta1, the fitted theta2 and L, and the default beta/Gamma.
// Throws std::invalid_argument when the measurements admit no law: an angle at or below theta1,
// equal angles, or thicknesses that do not fall as the angle rises.
PouliquenLaw invert_stopping_thickness(double theta1, const StopMeasurement& first,
                                       const StopMeasurement& second);

}  // namespace feedflow
