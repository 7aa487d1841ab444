#include "models/equipment/design_targets.hpp"

#include <algorithm>
#include <string_view>

#include "models/units/angle.hpp"

namespace feedflow {
namespace {
constexpr std::string_view kPatterns[] = {"mass", "funnel", "any"};
constexpr std::string_view kRegimes[] = {"any",       "slumping",    "rolling",
                                         "cascading", "cataracting", "centrifuging"};

struct KeyOwner {
  std::string_view key;
  EquipmentKind kind;
};
constexpr KeyOwner kOwners[] = {
    {"required_throughput", EquipmentKind::hopper},
    {"outlet_safety_factor", EquipmentKind::hopper},
    {"required_flow_pattern", EquipmentKind::hopper},
    {"mass_flow_margin", EquipmentKind::hopper},
    {"max_stopping_thickness", EquipmentKind::chute},
    {"required_regime", EquipmentKind::drum},
};
}  // namespace

std::span<const FieldSpec<DesignTargets>> design_target_fields() {
  using T = DesignTargets;
  static const FieldSpec<T> fields[] = {
      optional_number_field<T>("required_throughput", &T::required_throughput,
                               dim::mass_flow_rate, "kg/s", Range{0.0, 1e5, false, true},
                               "hopper: discharge rate the outlet must deliver"),
      number_field<T>("outlet_safety_factor", &T::outlet_safety_factor, dim::dimensionless, "-",
                      Range::closed(1.0, 10.0),
                      "hopper: the outlet must be at least this multiple of the critical width",
                      Presence::optional),
      label_field<T>("required_flow_pattern", &T::required_flow_pattern, kPatterns,
                     "hopper: flow pattern the design must achieve", Presence::optional),
      number_field<T>("mass_flow_margin", &T::mass_flow_margin, dim::angle, "deg",
                      Range::closed(0.0, 15.0 * kDegree),
                      "hopper: margin kept below the mass-flow limit angle", Presence::optional),
      optional_number_field<T>("max_stopping_thickness", &T::max_stopping_thickness,
                               dim::length, "mm", Range{0.0, 10.0, false, true},
                               "chute: largest deposit allowed to remain on the ramp"),
      label_field<T>("required_regime", &T::required_regime, kRegimes,
                     "drum: flow regime the drum must run in", Presence::optional),
  };
  return fields;
}

EquipmentKind design_target_kind(std::string_view key) {
  const auto owner = std::find_if(std::begin(kOwners), std::end(kOwners),
                                  [&](const KeyOwner& o) { return o.key == key; });
  return owner != std::end(kOwners) ? owner->kind : EquipmentKind::hopper;
}

std::vector<FieldProblem> check(const DesignTargets&, EquipmentKind kind,
                                std::span<const std::string> keys_given) {
  std::vector<FieldProblem> problems;
  for (const auto& key : keys_given) {
    const EquipmentKind owner = design_target_kind(key);
    if (owner != kind)
      problems.push_back({key, std::string("is a ") + to_string(owner) +
                                   " target; this is a " + to_string(kind) + " case"});
  }
  return problems;
}

}  // namespace feedflow
