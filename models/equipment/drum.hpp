#pragma once
// A horizontal rotating drum, partly filled, turning at constant speed.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "models/core/field_spec.hpp"

namespace feedflow {

struct Drum {
  double diameter = 0.0;                      // internal diameter [m]
  double length = 0.0;                        // internal length (end wall to end wall) [m]
  double fill_fraction = 0.0;                 // filled fraction of the cross-section [-]
  double speed = 0.0;                         // rotation speed [rad/s]
  std::optional<double> wall_friction_angle;  // material on the drum shell [rad]
};

std::span<const FieldSpec<Drum>> drum_fields();
std::vector<FieldProblem> check(const Drum& drum);

}  // namespace feedflow
