#include "reports/margin_table.hpp"

#include <algorithm>
#include <cmath>

#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

// In the finding's display unit when it has one (a target written in t/h), lengths in
// millimetres, other units as the judge gave them.
std::string shown(double v, const Finding& f) {
  if (!f.display_unit.empty() && f.display_unit != f.unit) {
    try {
      return format_quantity(v * parse_unit(f.unit).si, f.display_unit, 4);
    } catch (const UnitError&) {  // a unit the parser does not know: as the judge gave it
    }
  }
  if (f.unit == "m") return format_quantity(v, "mm", 4);
  return format_number(v, 4) + (f.unit.empty() ? "" : " " + f.unit);
}

int severity(VerdictStatus s) {
  switch (s) {
    case VerdictStatus::fail: return 3;
    case VerdictStatus::marginal: return 2;
    case VerdictStatus::unknown: return 1;
    case VerdictStatus::pass: return 0;
  }
  return 1;
}

}  // namespace

std::vector<MarginRow> margin_table(const Verdict& verdict) {
  std::vector<MarginRow> rows;
  for (const Finding& f : verdict.findings) {
    if (!f.status || !f.value || !f.limit || f.quantity.empty()) continue;
    const double value = *f.value, limit = *f.limit;
    const double low = f.low.value_or(value), high = f.high.value_or(value);
    // A ceiling (at_most) or a floor (at_least), from where the rules put the value and band.
    bool ceiling = false;
    switch (*f.status) {
      case VerdictStatus::pass: ceiling = high <= limit && !(low >= limit); break;
      case VerdictStatus::marginal: ceiling = value <= limit; break;
      case VerdictStatus::fail: ceiling = value > limit; break;
      case VerdictStatus::unknown: continue;
    }
    const double edge = ceiling ? high : low;  // the band's edge nearest the limit
    MarginRow r;
    r.check = quantity_label(f.quantity);
    r.requirement = std::string(ceiling ? "<= " : ">= ") + shown(limit, f);
    r.achieved =
        shown(value, f) +
        (f.low || f.high ? " (" + shown(low, f) + " .. " + shown(high, f) + ")" : std::string());
    r.relative_margin = limit != 0.0 ? (ceiling ? limit - edge : edge - limit) / std::abs(limit) : 0.0;
    r.margin = (r.relative_margin >= 0 ? "+" : "") + format_number(100.0 * r.relative_margin, 3) + " %";
    r.status = *f.status;
    rows.push_back(std::move(r));
  }
  const auto governing = std::max_element(rows.begin(), rows.end(), [](const MarginRow& a, const MarginRow& b) {
    if (severity(a.status) != severity(b.status)) return severity(a.status) < severity(b.status);
    return a.relative_margin > b.relative_margin;
  });
  if (governing != rows.end()) governing->governing = true;
  return rows;
}

}  // namespace feedflow
