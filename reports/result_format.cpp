#include "reports/result_format.hpp"

#include <algorithm>

#include "models/units/quantity_format.hpp"

namespace feedflow {

std::string quantity_label(const std::string& name) {
  std::string s = name.substr(name.rfind('.') == std::string::npos ? 0 : name.rfind('.') + 1);
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

std::string estimate_value_text(const Estimate& e) {
  if (!e.is_number()) return std::get<std::string>(e.value);
  return format_number(std::get<double>(e.value)) + (e.unit.empty() ? "" : " " + e.unit);
}

std::string estimate_band_text(const Estimate& e) {
  if (!e.low || !e.high) return "";
  return format_number(*e.low) + " .. " + format_number(*e.high) +
         (e.unit.empty() ? "" : " " + e.unit);
}

}  // namespace feedflow
