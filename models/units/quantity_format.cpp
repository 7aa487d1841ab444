#include "models/units/quantity_format.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "models/units/quantity_parser.hpp"

namespace feedflow {

std::string format_number(double value, int significant) {
  if (!std::isfinite(value)) return std::isnan(value) ? "NaN" : (value > 0 ? "inf" : "-inf");
  if (value == 0.0) return "0";
  char buf[64];
  const double magnitude = std::abs(value);
  if (magnitude >= 1e-3 && magnitude < 1e7) {
    const int digits_before = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
    const int decimals = std::max(0, significant - digits_before);
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    std::string s(buf);
    if (s.find('.') != std::string::npos) {
      while (s.back() == '0') s.pop_back();
      if (s.back() == '.') s.pop_back();
    }
    return s;
  }
  std::snprintf(buf, sizeof buf, "%.*g", significant, value);
  std::string s(buf);
  // "6e+08" -> "6e8", "1.5e-05" -> "1.5e-5"
  const auto e = s.find('e');
  if (e != std::string::npos) {
    std::string mantissa = s.substr(0, e);
    std::string exponent = s.substr(e + 1);
    const bool negative = exponent.front() == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    s = mantissa + "e" + (negative ? "-" : "") + exponent;
  }
  return s;
}

double convert_to(double si, std::string_view unit) { return si / parse_unit(unit).si; }

std::string format_quantity(double si, std::string_view unit, int significant) {
  const std::string number = format_number(convert_to(si, unit), significant);
  if (unit.empty() || unit == "-") return number;
  if (unit == "%" || unit == "\xC2\xB0") return number + std::string(unit);
  return number + " " + std::string(unit);
}

}  // namespace feedflow
