#pragma once
// The record of one design check or simulation: what was asked, with which inputs, what came
// out and the verdict. Every computing command produces one; reports/ writes it as JSON, text
// and (later) PDF.
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "models/core/chart.hpp"
#include "models/core/estimate.hpp"

namespace feedflow {

enum class EquipmentKind { hopper, chute, drum };
const char* to_string(EquipmentKind kind);
EquipmentKind equipment_kind_from_string(const std::string& text);  // throws std::invalid_argument

// One resolved input: dotted key, SI value (or text), SI unit, and how a person reads it.
struct InputValue {
  std::string key;                          // "hopper.semi_angle"
  std::variant<double, std::string, std::vector<double>> value;  // SI number(s) or a label
  std::string si_unit;                      // "rad"; empty for labels and pure numbers
  std::string display;                      // "30 deg"
  std::string source;                       // where the value comes from (materials); may be empty
};

enum class VerdictStatus { pass, marginal, fail, unknown };
const char* to_string(VerdictStatus status);
VerdictStatus verdict_status_from_string(const std::string& text);  // throws std::invalid_argument

struct Verdict {
  VerdictStatus status = VerdictStatus::unknown;
  std::vector<std::string> reasons;
};

struct DesignRecord {
  std::string feedflow_version;
  std::string case_name;
  EquipmentKind kind = EquipmentKind::hopper;
  std::string case_file;
  std::string description;
  std::vector<InputValue> inputs;
  std::vector<std::pair<std::string, Estimate>> results;  // quantity name -> estimate, in order
  Verdict verdict;
  std::vector<Chart> charts;          // curves for the report
  std::vector<std::string> assumptions;  // what the models assume, and which way each errs
  std::string command_line;           // how the record was produced
  double wall_seconds = 0.0;
};

}  // namespace feedflow
