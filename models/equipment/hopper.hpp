#pragma once
// A hopper as the designer describes it: converging section, outlet, fill and wall.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "models/core/field_spec.hpp"

namespace feedflow {

struct Hopper {
  std::string shape;                          // "wedge" (plane flow) or "conical"
  double semi_angle = 0.0;                    // wall angle from the vertical [rad]
  double outlet_width = 0.0;                  // slot width (wedge) or diameter (cone) [m]
  double fill_height = 0.0;                   // material top above the virtual apex [m]
  double bin_width = 0.0;                     // width (wedge) or diameter (cone) of the bin [m]
  std::optional<double> slot_length;          // out-of-plane length of a wedge's slot [m]
  std::optional<double> wall_friction_angle;  // hopper wall; the material's when absent [rad]

  bool is_wedge() const { return shape == "wedge"; }
  // Height of the apex-to-outlet cut-off and of the converging section, above the apex [m].
  double outlet_height() const;
  double transition_height() const;
  // Volume of material when filled to fill_height: the converging section between the outlet
  // and the transition, plus the bin above it. A wedge counts its slot length [m^3].
  double filled_volume() const;
};

std::span<const FieldSpec<Hopper>> hopper_fields();
std::vector<FieldProblem> check(const Hopper& hopper);

}  // namespace feedflow
