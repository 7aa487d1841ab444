#pragma once
// A result as the designer reports it: a value with its unit, its uncertainty band, the model
// that produced it and the rung of the fidelity ladder it stands on (DESIGN.md).
#include <optional>
#include <string>
#include <variant>

namespace feedflow {

enum class Rung { L0, L1, L2, L3 };

const char* to_string(Rung rung);
Rung rung_from_string(const std::string& text);  // throws std::invalid_argument

struct Estimate {
  std::variant<double, std::string> value;  // a number in `unit`, or a label ("mass", "rolling")
  std::string unit;                         // unit of value, low and high; empty for labels
  std::optional<double> low;                // lower end of the uncertainty band
  std::optional<double> high;               // upper end of the uncertainty band
  std::string model;                        // e.g. "Jenike/Enstad closed form"
  Rung rung = Rung::L0;
  std::string display_unit;                 // unit people read it in ("mm"); empty = `unit`

  bool is_number() const { return std::holds_alternative<double>(value); }
};

}  // namespace feedflow
