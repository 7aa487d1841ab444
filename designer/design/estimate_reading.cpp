#include "designer/design/estimate_reading.hpp"

#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {

const Estimate* number_of(const Estimates& estimates, std::string_view key) {
  const Estimate* e = find_estimate(estimates, key);
  return e && e->is_number() ? e : nullptr;
}

std::optional<std::string> label_of(const Estimates& estimates, std::string_view key) {
  const Estimate* e = find_estimate(estimates, key);
  if (!e || e->is_number()) return std::nullopt;
  return std::get<std::string>(e->value);
}

std::string shown(const Estimate& e, double value) {
  if (e.unit.empty() || e.unit == "-") return format_number(value, 3);
  try {
    const double si = value * parse_unit(e.unit).si;
    return format_quantity(si, e.display_unit.empty() ? e.unit : e.display_unit, 3);
  } catch (const UnitError&) {  // a unit the parser does not know: as stored
    return format_number(value, 3) + " " + e.unit;
  }
}

std::string shown(const Estimate& e) { return e.is_number() ? shown(e, std::get<double>(e.value)) : std::get<std::string>(e.value); }

std::string band_of(const Estimate& e) {
  if (!e.low || !e.high) return "";
  return shown(e, *e.low) + " .. " + shown(e, *e.high);
}

std::string shown_with_band(const Estimate& e) {
  if (!e.low || !e.high) return shown(e);
  return shown(e) + " (band " + band_of(e) + ")";
}

Finding finding(std::optional<VerdictStatus> status, std::string key, std::string text, const Estimate* e,
                std::optional<double> limit) {
  Finding f{status, std::move(key), std::move(text), std::nullopt, std::nullopt, std::nullopt, limit, ""};
  if (e && e->is_number()) {
    f.value = std::get<double>(e->value);
    f.low = e->low;
    f.high = e->high;
    f.unit = e->unit;
    f.display_unit = e->display_unit;
  }
  return f;
}

}  // namespace feedflow
