#include "reports/result_format.hpp"

#include <algorithm>

#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {

namespace {
constexpr const char* kReducedModelSuffix = "_reduced_model";
}  // namespace

std::string reduced_model_key(const std::string& name) { return name + kReducedModelSuffix; }

std::string quantity_label(const std::string& name) {
  // A dotted key ("material.bulk.density") reads as its last part; text with spaces (a sweep
  // point's "semi_angle = 12.5 deg") keeps its dots.
  const bool key = name.find(' ') == std::string::npos;
  std::string s =
      key && name.rfind('.') != std::string::npos ? name.substr(name.rfind('.') + 1) : name;
  const std::string suffix = kReducedModelSuffix;
  const bool reduced = s.size() > suffix.size() && s.ends_with(suffix);
  if (reduced) s.resize(s.size() - suffix.size());
  std::replace(s.begin(), s.end(), '_', ' ');
  return reduced ? s + " (reduced model)" : s;
}

namespace {
// The value in the unit people read: display_unit when it converts from unit.
std::string in_display_unit(const Estimate& e, double v, bool with_unit) {
  std::string unit = e.unit;
  if (!e.display_unit.empty() && e.display_unit != e.unit) {
    try {
      v = convert_to(v * parse_unit(e.unit).si, e.display_unit);
      unit = e.display_unit;
    } catch (const UnitError&) {  // not convertible: keep the stored unit
    }
  }
  return format_number(v) + (with_unit && !unit.empty() && unit != "-" ? " " + unit : "");
}
}  // namespace

std::string estimate_value_text(const Estimate& e) {
  if (!e.is_number()) return std::get<std::string>(e.value);
  return in_display_unit(e, std::get<double>(e.value), true);
}

std::string estimate_band_text(const Estimate& e) {
  if (!e.low || !e.high) return "";
  return in_display_unit(e, *e.low, false) + " .. " + in_display_unit(e, *e.high, true);
}

}  // namespace feedflow
