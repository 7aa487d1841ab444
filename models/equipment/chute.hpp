#pragma once
// An inclined chute (plane) fed from a storage bin through a lifted gate, as in the seed's
// full-scale inclined-plane test.
#include <span>
#include <string>
#include <vector>

#include "models/core/field_spec.hpp"

namespace feedflow {

struct Chute {
  double angle = 0.0;         // ramp inclination from the horizontal [rad]
  double width = 0.0;         // ramp width [m]
  double length = 0.0;        // ramp length along the slope [m]
  double gate_opening = 0.0;  // height of the gate opening above the ramp [m]
  double bin_length = 0.0;    // storage bin length along the ramp direction [m]
  double bin_height = 0.0;    // storage bin height [m]
  double fill_height = 0.0;   // material height in the bin before release [m]
};

std::span<const FieldSpec<Chute>> chute_fields();
std::vector<FieldProblem> check(const Chute& chute);

}  // namespace feedflow
