#include "designer/sweep/sweep_axis.hpp"

#include <cmath>
#include <cstdio>
#include <regex>
#include <sstream>

#include "designer/case/simulation_settings.hpp"
#include "models/core/errors.hpp"
#include "models/equipment/chute.hpp"
#include "models/equipment/design_targets.hpp"
#include "models/equipment/drum.hpp"
#include "models/equipment/hopper.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

constexpr std::size_t kMaxValues = 100000;

[[noreturn]] void refuse(const std::string& text, const std::string& what) {
  throw InputError("--vary", text, what);
}

template <class Record>
CaseKeyKind kind_in(std::span<const FieldSpec<Record>> fields, const std::string& key) {
  for (const auto& f : fields)
    if (f.key == key) {
      CaseKeyKind k;
      k.known = true;
      k.label = f.is_label();
      k.dimension = f.dimension;
      k.display_unit = std::string(f.display_unit);
      return k;
    }
  return {};
}

// A number and the unit written after it ("15deg", "0.5 m", "20"); nullopt if not a number.
struct Written {
  double number = 0.0;
  std::string unit;
};
std::optional<Written> split_number(const std::string& token) {
  static const std::regex number_unit(
      R"(^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$)");
  std::smatch m;
  if (!std::regex_match(token, m, number_unit)) return std::nullopt;
  return Written{std::stod(m[1].str()), m[2].str()};
}

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\"'");
  const auto b = s.find_last_not_of(" \t\"'");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// The SI factor of `unit` ("" is 1), refused naming the flag when it is no unit.
Quantity unit_of(const std::string& unit, const std::string& text) {
  if (unit.empty()) return {1.0, dim::dimensionless};
  try {
    return parse_unit(unit);
  } catch (const UnitError& e) {
    refuse(text, "\"" + unit + "\" is not a unit: " + e.what());
  }
}

// The values' unit: the one written (all written ones of one dimension), checked against what
// the key takes.
std::string common_unit(const std::vector<std::string>& written, const CaseKeyKind& kind,
                        const std::string& key, const std::string& text) {
  std::string unit;
  for (const auto& u : written) {
    if (u.empty()) continue;
    if (unit.empty()) {
      unit = u;
    } else if (!(unit_of(u, text).dimension == unit_of(unit, text).dimension)) {
      refuse(text, "the range mixes \"" + unit + "\" and \"" + u + "\"");
    }
  }
  if (kind.known && !kind.label && !(kind.dimension == dim::dimensionless)) {
    if (unit.empty())
      refuse(text, key + " is a " + dimension_name(kind.dimension) +
                       ": give the range a unit, e.g. " + key + "=1..2" + kind.display_unit + ":5");
    if (!(unit_of(unit, text).dimension == kind.dimension))
      refuse(text, key + " is a " + dimension_name(kind.dimension) + "; \"" + unit +
                       "\" measures " + dimension_name(unit_of(unit, text).dimension) +
                       " (write it in " + kind.display_unit + ", for one)");
  }
  return unit;
}

// "17.5 deg" for the loader (and its SI value): the number in the written unit, to 12 digits.
SweepValue value_of(double number, const std::string& unit, const std::string& text,
                    int significant = 12) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, number);
  SweepValue v;
  v.text = unit.empty() ? std::string(buf) : std::string(buf) + " " + unit;
  v.si = std::strtod(buf, nullptr) * unit_of(unit, text).si;  // the value the text says
  return v;
}

void parse_range(const std::string& range, const std::string& text, const CaseKeyKind& kind,
                 SweepAxis& axis) {
  const auto dots = range.find("..");
  const std::string from_text = range.substr(0, dots);
  std::string rest = range.substr(dots + 2);
  std::string to_text, step_text, count_text;
  if (const auto slash = rest.find('/'); slash != std::string::npos) {
    to_text = rest.substr(0, slash);
    step_text = rest.substr(slash + 1);
  } else if (const auto colon = rest.find(':'); colon != std::string::npos) {
    to_text = rest.substr(0, colon);
    count_text = trimmed(rest.substr(colon + 1));
  } else {
    refuse(text,
           "a range needs a step or a count: A..B/STEP (15..40deg/5deg) or A..B:N "
           "(20..100mm:9, or :5log for log spacing)");
  }
  const auto from = split_number(from_text), to = split_number(to_text);
  if (!from || !to) refuse(text, "the ends of the range must be numbers (with a unit)");
  std::optional<Written> step;
  if (!step_text.empty()) {
    step = split_number(step_text);
    if (!step) refuse(text, "the step after / must be a number (with a unit)");
  }
  axis.unit = common_unit({from->unit, to->unit, step ? step->unit : ""}, kind, axis.key, text);
  // Each end in the common unit.
  const double unit_si = unit_of(axis.unit, text).si;
  auto in_unit = [&](const Written& w) {
    return w.unit.empty() ? w.number : w.number * unit_of(w.unit, text).si / unit_si;
  };
  const double a = in_unit(*from), b = in_unit(*to);
  if (!(b > a)) refuse(text, "the range is empty: its end must be above its start");
  axis.span = SweepAxis::Span{a * unit_si, b * unit_si, false};
  if (step) {
    const double s = in_unit(*step);
    if (!(s > 0.0)) refuse(text, "the step must be positive");
    const double n = std::floor((b - a) / s * (1.0 + 1e-12) + 1e-9) + 1.0;
    if (n > static_cast<double>(kMaxValues)) refuse(text, "more than 100 000 values");
    for (int k = 0; k < static_cast<int>(n); ++k)
      axis.values.push_back(value_of(a + k * s, axis.unit, text));
    return;
  }
  const bool log = count_text.size() > 3 && count_text.substr(count_text.size() - 3) == "log";
  const std::string digits = log ? count_text.substr(0, count_text.size() - 3) : count_text;
  char* end = nullptr;
  const long n = std::strtol(digits.c_str(), &end, 10);
  if (digits.empty() || *end != '\0' || n < 2 || n > static_cast<long>(kMaxValues))
    refuse(text,
           "the count after : must be a whole number from 2 to 100 000 (\"" + count_text + "\")");
  if (log && !(a > 0.0)) refuse(text, "a log range needs a positive start");
  axis.span->log = log;
  for (long k = 0; k < n; ++k) {
    const double f = static_cast<double>(k) / static_cast<double>(n - 1);
    const double x = k == n - 1 ? b : log ? a * std::pow(b / a, f) : a + f * (b - a);
    axis.values.push_back(value_of(x, axis.unit, text));
  }
}

void parse_list(const std::string& list, const std::string& text, const CaseKeyKind& kind,
                SweepAxis& axis) {
  std::vector<std::string> items;
  std::stringstream split(list);
  for (std::string item; std::getline(split, item, ',');) items.push_back(trimmed(item));
  for (const auto& item : items)
    if (item.empty()) refuse(text, "an empty item in the list");
  std::vector<std::optional<Written>> numbers;
  bool all_numbers = true;
  for (const auto& item : items) {
    numbers.push_back(split_number(item));
    all_numbers = all_numbers && numbers.back();
  }
  if (!all_numbers) {
    if (kind.known && !kind.label)
      refuse(text, axis.key + " takes numbers" +
                       (kind.display_unit.empty() ? std::string() : " in " + kind.display_unit) +
                       ", not words");
    for (const auto& item : items) axis.values.push_back({item, std::nullopt});
    return;
  }
  if (kind.known && kind.label) refuse(text, axis.key + " takes words, not numbers");
  std::vector<std::string> units;
  for (const auto& n : numbers) units.push_back(n->unit);
  axis.unit = common_unit(units, kind, axis.key, text);
  const double unit_si = unit_of(axis.unit, text).si;
  for (const auto& n : numbers) {
    const double x = n->unit.empty() ? n->number : n->number * unit_of(n->unit, text).si / unit_si;
    axis.values.push_back(value_of(x, axis.unit, text));
  }
}

}  // namespace

CaseKeyKind case_key_kind(const std::string& case_key) {
  const auto dot = case_key.find('.');
  if (dot == std::string::npos) return {};
  const std::string table = case_key.substr(0, dot), key = case_key.substr(dot + 1);
  if (table == "hopper") return kind_in(hopper_fields(), key);
  if (table == "chute") return kind_in(chute_fields(), key);
  if (table == "drum") return kind_in(drum_fields(), key);
  if (table == "design") return kind_in(design_target_fields(), key);
  if (table == "dem") return kind_in(dem_case_fields(), key);
  if (table == "cel") return kind_in(cel_case_fields(), key);
  if (case_key == "case.material") return {true, true, {}, ""};
  return {};
}

double axis_unit_si(const SweepAxis& axis) { return unit_of(axis.unit, axis.key).si; }

SweepValue axis_value(const SweepAxis& axis, double si, int significant) {
  return value_of(si / unit_of(axis.unit, axis.key).si, axis.unit, axis.key, significant);
}

SweepAxis parse_sweep_axis(const std::string& text, const std::string& flag) {
  if (flag != "--vary") {  // the same rules, the faults named by the flag given
    try {
      return parse_sweep_axis(text);
    } catch (const InputError& e) {
      throw InputError(flag, e.key(), e.message());
    }
  }
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    refuse(text, "expected KEY=RANGE, e.g. --vary hopper.semi_angle=15..40deg/5deg");
  SweepAxis axis;
  axis.key = trimmed(text.substr(0, eq));
  axis.case_key = axis.key == "material" ? "case.material" : axis.key;
  const std::string range = trimmed(text.substr(eq + 1));
  const CaseKeyKind kind = case_key_kind(axis.case_key);
  const auto dot = axis.case_key.find('.');
  const std::string table = dot == std::string::npos ? "" : axis.case_key.substr(0, dot);
  const bool material_key = table == "material";
  if (!kind.known && !material_key)
    refuse(text, "unknown key \"" + axis.key +
                     "\": vary a [hopper], [chute], [drum], [design], [dem], [cel] or material.* "
                     "value of the case, or material=NAME,NAME");
  if (range.find("..") != std::string::npos)
    parse_range(range, text, kind, axis);
  else
    parse_list(range, text, kind, axis);
  if (axis.values.empty()) refuse(text, "the range gives no value");
  return axis;
}

}  // namespace feedflow
