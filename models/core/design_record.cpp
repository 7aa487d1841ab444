#include "models/core/design_record.hpp"

#include <stdexcept>

namespace feedflow {

const char* to_string(EquipmentKind kind) {
  switch (kind) {
    case EquipmentKind::hopper: return "hopper";
    case EquipmentKind::chute: return "chute";
    case EquipmentKind::drum: return "drum";
  }
  return "hopper";
}

EquipmentKind equipment_kind_from_string(const std::string& text) {
  if (text == "hopper") return EquipmentKind::hopper;
  if (text == "chute") return EquipmentKind::chute;
  if (text == "drum") return EquipmentKind::drum;
  throw std::invalid_argument("kind must be hopper, chute or drum, got \"" + text + "\"");
}

const char* to_string(VerdictStatus status) {
  switch (status) {
    case VerdictStatus::pass: return "pass";
    case VerdictStatus::marginal: return "marginal";
    case VerdictStatus::fail: return "fail";
    case VerdictStatus::unknown: return "unknown";
  }
  return "unknown";
}

const Estimate* find_estimate(const Estimates& estimates, std::string_view key) {
  for (const auto& [name, e] : estimates)
    if (name == key) return &e;
  return nullptr;
}

std::string interval_key(std::string_view key) { return std::string(key) + "_interval"; }

VerdictStatus verdict_status_from_string(const std::string& text) {
  if (text == "pass") return VerdictStatus::pass;
  if (text == "marginal") return VerdictStatus::marginal;
  if (text == "fail") return VerdictStatus::fail;
  if (text == "unknown") return VerdictStatus::unknown;
  throw std::invalid_argument("verdict status must be pass, marginal, fail or unknown, got \"" +
                              text + "\"");
}

}  // namespace feedflow
