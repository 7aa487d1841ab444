#pragma once
// A design case as read from a case file (cases/*.toml) with command-line overrides applied:
// the equipment, the material and the engineer's targets, all in SI.
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "designer/case/simulation_settings.hpp"
#include "models/core/design_record.hpp"
#include "models/equipment/chute.hpp"
#include "models/equipment/design_targets.hpp"
#include "models/equipment/drum.hpp"
#include "models/equipment/hopper.hpp"
#include "models/material/material.hpp"

namespace feedflow {

struct Case {
  std::string name;         // [case] name, or the file's stem
  std::string description;  // one line
  std::string file;         // path as given
  Material material;
  std::variant<Hopper, Chute, Drum> equipment;
  DesignTargets design;
  DemCaseSettings dem;  // [dem]: how `feedflow simulate --solver dem` runs the case
  CelCaseSettings cel;  // [cel]: how `feedflow simulate --solver cel` runs the case
  std::vector<std::string> warnings;  // accepted, but the engineer should know
  // Dotted key -> the unit its value was written in, where one was (written_units.hpp).
  std::map<std::string, std::string> written_units = {};

  EquipmentKind kind() const { return static_cast<EquipmentKind>(equipment.index()); }
};

// One `--set key=value` override.
struct SetOverride {
  std::string key;    // dotted: "hopper.semi_angle"
  std::string value;  // as typed: "32deg", "0.5", "wedge"
};

// Splits "key=value"; throws InputError for text without '=' or with an empty key.
SetOverride parse_set_override(const std::string& text);

}  // namespace feedflow
