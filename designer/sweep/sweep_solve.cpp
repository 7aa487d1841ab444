#include "designer/sweep/sweep_solve.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr int kMaxBisections = 200;

struct Probe {
  double si = 0.0;
  SweepPoint point;
  std::optional<bool> met;  // nullopt: the case refused the value or the result is missing
};

// The value of the target's result at a probe, in words ("mass_flow_rate = 4.81 kg/s").
std::string result_words(const SweepTarget& t, const SweepPoint& p) {
  const Estimate* e = find_estimate(p.results, t.quantity);
  if (!e) return t.quantity + " is not answered";
  if (!e->is_number()) return t.quantity + " = " + std::get<std::string>(e->value);
  const double x = t.band_end == "low" && e->low     ? *e->low
                   : t.band_end == "high" && e->high ? *e->high
                                                     : std::get<double>(e->value);
  return t.quantity + (t.band_end.empty() ? "" : "." + t.band_end) + " = " + format_number(x) +
         (e->unit.empty() ? "" : " " + e->unit);
}

// What stands beyond the boundary: the checks that set the verdict there, or the target's result.
void describe_beyond(const SweepTarget& t, const SweepAxis& axis, const Probe& beyond,
                     SweepSolution& s) {
  s.beyond_text = axis_value(axis, beyond.si, 6).text;
  s.beyond_verdict = beyond.point.verdict;
  if (t.kind == SweepTarget::Kind::verdict) {
    s.beyond_governing = beyond.point.governing;
    s.beyond_reason = beyond.point.governing_reason;
  } else {
    s.beyond_governing = {t.quantity};
    s.beyond_reason = result_words(t, beyond.point);
  }
}

// How far a point is from meeting the target: the target's own distance, ties (equal verdicts)
// broken by how far the governing results are from their limits, relative (in [0, 1)).
std::pair<double, double> nearness(const SweepTarget& t, const SweepPoint& p) {
  double shortfall = 0.0;
  for (const auto& [quantity, limit] : p.limits) {
    if (std::find(p.governing.begin(), p.governing.end(), quantity) == p.governing.end()) continue;
    const Estimate* e = find_estimate(p.results, quantity);
    if (!e || !e->is_number()) continue;
    const double v = std::get<double>(e->value);
    if (std::abs(v) + std::abs(limit) > 0.0)
      shortfall = std::max(shortfall, std::abs(v - limit) / (std::abs(v) + std::abs(limit)));
  }
  return {distance_to_target(t, p.verdict, p.results), shortfall};
}

// Digits that show a value to a tenth of the tolerance.
int digits_for(double si, double tolerance) {
  if (!(tolerance > 0.0) || si == 0.0) return 6;
  const int d = static_cast<int>(std::ceil(std::log10(std::abs(si) / tolerance))) + 1;
  return std::clamp(d, 3, 12);
}

}  // namespace

double default_solve_tolerance(const SweepAxis& axis) {
  double lo = *axis.values.front().si, hi = lo;
  for (const auto& v : axis.values) {
    lo = std::min(lo, *v.si);
    hi = std::max(hi, *v.si);
  }
  return (hi - lo) / 1000.0;
}

SweepPoint solve_point(const SweepRequest& request, const std::vector<std::size_t>& index) {
  const auto start = std::chrono::steady_clock::now();
  const SweepSolve& solve = *request.solve;
  const SweepAxis& axis = solve.axis;
  const std::vector<SetOverride> base = point_overrides(request, index);
  SweepSolution s;
  auto probe = [&](const SweepValue& v) {
    std::vector<SetOverride> sets = base;
    sets.push_back({axis.case_key, v.text});
    Probe p{*v.si, answer_overrides(request, sets), std::nullopt};
    if (p.point.done) p.met = meets_target(solve.target, p.point.verdict, p.point.results);
    ++s.evaluations;
    return p;
  };
  std::vector<Probe> scan;
  for (const auto& v : axis.values) scan.push_back(probe(v));
  std::stable_sort(scan.begin(), scan.end(),
                   [](const Probe& a, const Probe& b) { return a.si < b.si; });
  std::vector<std::size_t> known;
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (scan[i].met) known.push_back(i);

  auto finish = [&](SweepPoint p) {
    p.index = index;
    p.solution = s;
    p.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return p;
  };
  const std::string range = axis.values.size() > 1
                                ? axis_value(axis, scan.front().si, 6).text + " .. " +
                                      axis_value(axis, scan.back().si, 6).text
                                : axis_value(axis, scan.front().si, 6).text;
  if (known.empty()) {
    SweepPoint p;
    p.error = "no value of " + axis.key + " in " + range + " could be checked; at " +
              axis.values.front().text + ": " +
              (scan.front().point.done ? solve.target.quantity + " is not answered"
                                       : scan.front().point.error);
    return finish(p);
  }
  std::optional<std::size_t> first;  // the first crossing: between known[first] and known[first+1]
  for (std::size_t k = 0; k + 1 < known.size(); ++k)
    if (*scan[known[k]].met != *scan[known[k + 1]].met) {
      ++s.crossings;
      if (!first) first = k;
    }

  if (!first) {
    if (*scan[known.front()].met) {  // met everywhere: the point is answered at the first value
      s.outcome = SweepSolution::Outcome::met_everywhere;
      s.bracket_low = scan.front().si;
      s.bracket_high = scan.back().si;
      return finish(scan[known.front()].point);
    }
    // Never met: the nearest scanned value says why.
    s.outcome = SweepSolution::Outcome::never_met;
    std::size_t nearest = known.front();
    for (std::size_t i : known)
      if (nearness(solve.target, scan[i].point) < nearness(solve.target, scan[nearest].point))
        nearest = i;
    describe_beyond(solve.target, axis, scan[nearest], s);
    SweepPoint p = scan[nearest].point;
    p.done = false;
    p.error = "no " + axis.key + " in " + range + " " + solve.target.describe() + "; nearest at " +
              s.beyond_text + ": " + to_string(s.beyond_verdict) +
              (s.beyond_reason.empty() ? "" : ": " + s.beyond_reason);
    return finish(p);
  }

  // Narrows [lo, hi] (met differently at the two ends, by `met_by`) to the tolerance.
  auto bisect = [&](Probe& lo, Probe& hi, auto met_by) {
    for (int i = 0; i < kMaxBisections && hi.si - lo.si > solve.tolerance; ++i) {
      Probe mid = probe(axis_value(axis, 0.5 * (lo.si + hi.si)));
      const std::optional<bool> met = met_by(mid);
      if (!met) break;  // the case refuses the value or the model does not answer: stop here
      (*met == *met_by(lo) ? lo : hi) = std::move(mid);
    }
  };
  Probe lo = scan[known[*first]], hi = scan[known[*first + 1]];
  s.smallest = !*lo.met;
  bisect(lo, hi, [](const Probe& p) { return p.met; });
  s.outcome = SweepSolution::Outcome::solved;
  s.bracket_low = lo.si;
  s.bracket_high = hi.si;
  const Probe& meeting = s.smallest ? hi : lo;
  const Probe& beyond = s.smallest ? lo : hi;
  s.value = meeting.si;
  s.text = axis_value(axis, meeting.si, digits_for(meeting.si, solve.tolerance)).text;
  describe_beyond(solve.target, axis, beyond, s);
  // A pass target: where MARGINAL begins on the same side, the other edge of the design band.
  if (solve.target.kind == SweepTarget::Kind::verdict &&
      solve.target.worst_meeting == VerdictStatus::pass) {
    const SweepTarget not_fail = parse_sweep_target("not-fail");
    auto not_failing = [&](const Probe& p) -> std::optional<bool> {
      if (!p.point.done) return std::nullopt;
      return meets_target(not_fail, p.point.verdict, p.point.results);
    };
    for (std::size_t k = 0; k + 1 < scan.size(); ++k) {
      const auto a = not_failing(scan[k]), b = not_failing(scan[k + 1]);
      if (!a || !b || *a == *b || *b != s.smallest) continue;
      Probe m_lo = scan[k], m_hi = scan[k + 1];
      bisect(m_lo, m_hi, not_failing);
      s.marginal_from = s.smallest ? m_hi.si : m_lo.si;
      break;
    }
  }
  return finish(meeting.point);
}

}  // namespace feedflow
