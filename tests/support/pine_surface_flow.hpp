#pragma once
// The pine's surface-flow law as Table 1's targets give it (reduced_models.md section 3): theta1
// 27 deg, theta2 40 deg, L 10 mm, beta 0.136, for the chute tests that do not read the material.
#include "models/chute/pouliquen_law.hpp"
#include "models/units/angle.hpp"

namespace feedflow::testing {

inline PouliquenLaw pine_like() { return {27 * kDegree, 40 * kDegree, 10e-3, 0.136, 0.0}; }

}  // namespace feedflow::testing
