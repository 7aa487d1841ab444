#pragma once
// What the engineer requires of the equipment: the `[design]` table of a case. A verdict is
// judged against these targets.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "models/core/design_record.hpp"
#include "models/core/field_spec.hpp"

namespace feedflow {

struct DesignTargets {
  // Hopper
  std::optional<double> required_throughput;  // mass flow rate the outlet must deliver [kg/s]
  double outlet_safety_factor = 1.0;          // outlet must be >= this x critical width [-]
  std::string required_flow_pattern = "any";  // "mass", "funnel" or "any"
  double mass_flow_margin = 0.05235987755982988;  // margin on the mass-flow angle [rad] (3 deg)
  // Chute
  std::optional<double> max_stopping_thickness;  // deposit allowed to remain on the chute [m]
  // Drum
  std::string required_regime = "any";  // "rolling", "cascading", ... or "any"
};

std::span<const FieldSpec<DesignTargets>> design_target_fields();

// The kind of equipment a target key belongs to ("max_stopping_thickness" -> chute).
EquipmentKind design_target_kind(std::string_view key);

// Targets that make no sense for `kind` (a chute target in a hopper case, ...).
std::vector<FieldProblem> check(const DesignTargets& targets, EquipmentKind kind,
                                std::span<const std::string> keys_given);

}  // namespace feedflow
