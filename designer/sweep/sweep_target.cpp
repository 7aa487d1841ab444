#include "designer/sweep/sweep_target.hpp"

#include <array>
#include <cmath>
#include <regex>

#include "designer/case/did_you_mean.hpp"
#include "models/core/errors.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

[[noreturn]] void refuse(const std::string& text, const std::string& what) {
  throw InputError("--target", text, what);
}

int rank(VerdictStatus s) {
  switch (s) {
    case VerdictStatus::pass: return 0;
    case VerdictStatus::marginal: return 1;
    case VerdictStatus::fail: return 2;
    case VerdictStatus::unknown: return 3;
  }
  return 3;
}

// The number a target reads off an estimate: its value or one end of its band.
std::optional<double> reading(const SweepTarget& t, const Estimate& e) {
  if (!e.is_number()) return std::nullopt;
  if (t.band_end == "low") return e.low;
  if (t.band_end == "high") return e.high;
  return std::get<double>(e.value);
}

std::string result_list(const Estimates& results) {
  std::string s;
  for (const auto& [key, e] : results) s += (s.empty() ? "" : ", ") + key;
  return s;
}

}  // namespace

std::string SweepTarget::describe() const {
  if (kind == Kind::verdict)
    return worst_meeting == VerdictStatus::pass ? "passes" : "passes or is marginal";
  return text;
}

SweepTarget parse_sweep_target(const std::string& text) {
  SweepTarget t;
  t.text = text;
  if (text == "pass") return t;
  if (text == "not-fail") {
    t.worst_meeting = VerdictStatus::marginal;
    return t;
  }
  static const std::regex condition(
      R"(^\s*([A-Za-z_][A-Za-z_0-9]*)(?:\.(low|high))?\s*(>=|<=|!=|>|<|=)\s*(.*?)\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, condition))
    refuse(text,
           "expected pass, not-fail, RESULT>=VALUE (mass_flow_rate>=5kg/s; also >, <=, <, = for "
           "the crossing, RESULT.low or RESULT.high for an end of its band) or RESULT=WORD "
           "(flow_pattern=mass, regime!=rolling)");
  t.quantity = m[1].str();
  t.band_end = m[2].str();
  const std::string op = m[3].str(), rhs = m[4].str();
  if (rhs.empty()) refuse(text, "the condition has no value after " + op);
  static const std::regex number_unit(R"(^([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*)$)");
  std::smatch n;
  if (std::regex_match(rhs, n, number_unit)) {
    t.kind = SweepTarget::Kind::number;
    t.value = std::stod(n[1].str());
    t.written_unit = n[2].str();
    if (op == "!=") refuse(text, "a number is compared with >=, >, <=, < or = (its crossing)");
    t.compare = op == ">="   ? SweepTarget::Compare::at_least
                : op == ">"  ? SweepTarget::Compare::above
                : op == "<=" ? SweepTarget::Compare::at_most
                : op == "<"  ? SweepTarget::Compare::below
                             : SweepTarget::Compare::crosses;
    return t;
  }
  t.kind = SweepTarget::Kind::label;
  t.word = rhs;
  if (!t.band_end.empty()) refuse(text, "a word result has no band (." + t.band_end + ")");
  if (op != "=" && op != "!=") refuse(text, "a word is compared with = or !=, not " + op);
  t.compare = op == "=" ? SweepTarget::Compare::equal : SweepTarget::Compare::not_equal;
  return t;
}

void check_sweep_target(SweepTarget& t, const Estimates& results) {
  if (t.kind == SweepTarget::Kind::verdict) return;
  const Estimate* e = find_estimate(results, t.quantity);
  if (!e) {
    std::vector<std::string_view> keys;
    for (const auto& [key, est] : results) keys.push_back(key);
    refuse(t.text, "the design check has no result \"" + t.quantity + "\"" +
                       did_you_mean(t.quantity, keys) + "; its results: " + result_list(results));
  }
  if (t.kind == SweepTarget::Kind::label) {
    if (e->is_number())
      refuse(t.text, t.quantity + " is a number" +
                         (e->unit.empty() ? std::string() : " in " + e->unit) +
                         ": compare it with >=, <=, > , < or =, e.g. " + t.quantity +
                         ">=" + (e->unit.empty() ? "1" : "1 " + e->unit));
    return;
  }
  if (!e->is_number())
    refuse(t.text, t.quantity + " is a word (\"" + std::get<std::string>(e->value) +
                       "\" for this case): write " + t.quantity + "=WORD");
  if (!t.band_end.empty() && !reading(t, *e))
    refuse(t.text, t.quantity + " has no band to take the " + t.band_end + " end of");
  Quantity result_unit{1.0, dim::dimensionless}, written{1.0, dim::dimensionless};
  try {
    if (!e->unit.empty()) result_unit = parse_unit(e->unit);
    if (!t.written_unit.empty()) written = parse_unit(t.written_unit);
  } catch (const UnitError& err) {
    refuse(t.text, "\"" + t.written_unit + "\" is not a unit: " + err.what());
  }
  const std::string shown = e->display_unit.empty() ? e->unit : e->display_unit;
  if (t.written_unit.empty() && !(result_unit.dimension == dim::dimensionless))
    refuse(t.text, t.quantity + " is a " + dimension_name(result_unit.dimension) +
                       ": give the value a unit, e.g. " + t.quantity + ">=1 " + shown);
  if (!(written.dimension == result_unit.dimension))
    refuse(t.text, t.quantity + " is a " + dimension_name(result_unit.dimension) + "; \"" +
                       t.written_unit + "\" measures " + dimension_name(written.dimension) +
                       " (write it in " + shown + ", for one)");
  t.value = t.value * written.si / result_unit.si;
}

std::optional<bool> meets_target(const SweepTarget& t, VerdictStatus verdict,
                                 const Estimates& results) {
  if (t.kind == SweepTarget::Kind::verdict) return rank(verdict) <= rank(t.worst_meeting);
  const Estimate* e = find_estimate(results, t.quantity);
  if (!e) return std::nullopt;
  if (t.kind == SweepTarget::Kind::label) {
    if (e->is_number()) return std::nullopt;
    const bool same = std::get<std::string>(e->value) == t.word;
    return t.compare == SweepTarget::Compare::equal ? same : !same;
  }
  const auto x = reading(t, *e);
  if (!x || !std::isfinite(*x)) return std::nullopt;
  switch (t.compare) {
    case SweepTarget::Compare::at_least:
    case SweepTarget::Compare::crosses: return *x >= t.value;
    case SweepTarget::Compare::above: return *x > t.value;
    case SweepTarget::Compare::at_most: return *x <= t.value;
    case SweepTarget::Compare::below: return *x < t.value;
    default: return std::nullopt;
  }
}

double distance_to_target(const SweepTarget& t, VerdictStatus verdict, const Estimates& results) {
  if (t.kind == SweepTarget::Kind::verdict) return rank(verdict);
  const Estimate* e = find_estimate(results, t.quantity);
  if (t.kind == SweepTarget::Kind::label || !e) return e ? 0.0 : 1e300;
  const auto x = reading(t, *e);
  return x && std::isfinite(*x) ? std::abs(*x - t.value) : 1e300;
}

}  // namespace feedflow
