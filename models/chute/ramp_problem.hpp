#pragma once
// The L1 chute problem statement shared by the scheme, its reconstruction and the solver: the
// 1-D grid along the ramp, the slope, the basal law, the ends and the gate.
#include <cstddef>
#include <optional>

#include "models/chute/pouliquen_law.hpp"

namespace feedflow {

enum class RampBoundary {
  Wall,      // closed end: no mass flux, pressure reaction
  Outflow,   // free lower end: a ghost continues the ramp; material leaves, never enters
             // (downstream only)
  Periodic,  // the two ends joined (uniform-flow tests)
};

struct RampGrid {
  double x_begin = 0.0;  // upstream end [m]
  double x_end = 0.0;    // downstream end [m]
  std::size_t cells = 0;
  double dx() const { return (x_end - x_begin) / static_cast<double>(cells); }
  double centre(std::size_t i) const { return x_begin + (static_cast<double>(i) + 0.5) * dx(); }
};

struct RampPhysics {
  double angle = 0.0;           // ramp inclination [rad]
  PouliquenLaw friction;        // basal law; theta1 == theta2 is a Coulomb law, 0 == 0 none
  double earth_pressure = 1.0;  // k [-]
  RampBoundary upstream = RampBoundary::Wall;
  RampBoundary downstream = RampBoundary::Outflow;
  std::optional<std::size_t> gate_face;  // face index (0..cells) carrying a gate
  double gate_opening = 0.0;             // clear height under the gate [m]
  double dry_thickness = 1e-10;          // thinner cells have no velocity [m]
};

}  // namespace feedflow
