#include "designer/sweep/sweep_charts.hpp"

#include <cmath>
#include <map>
#include <optional>

#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

constexpr std::size_t kMaxCurves = 8;
constexpr std::size_t kMaxResultCharts = 6;

double number_of(const SweepValue& v) { return std::stod(v.text); }

std::string label_of(const SweepAxis& a) {
  return a.key.substr(a.key.find('.') == std::string::npos ? 0 : a.key.find('.') + 1);
}

// The factor from a result's unit to the unit people read it in, and that unit.
std::pair<double, std::string> display_of(const Estimate& e) {
  if (e.display_unit.empty() || e.display_unit == e.unit) return {1.0, e.unit};
  try {
    const double from = e.unit.empty() ? 1.0 : parse_unit(e.unit).si;
    return {from / parse_unit(e.display_unit).si, e.display_unit};
  } catch (const UnitError&) {
    return {1.0, e.unit};
  }
}

struct Layout {
  std::optional<std::size_t> x;       // the first numeric axis
  std::optional<std::size_t> family;  // the next axis, one curve per value
};

Layout layout_of(const SweepRequest& r) {
  Layout l;
  for (std::size_t k = 0; k < r.axes.size(); ++k) {
    if (!l.x && r.axes[k].numeric())
      l.x = k;
    else if (!l.family && !r.sampled && r.axes[k].values.size() <= kMaxCurves)
      l.family = k;
  }
  return l;
}

// The points of each curve: the family value's index -> the points' numbers, in x order.
std::map<std::size_t, std::vector<std::size_t>> curves(const SweepRequest& r, const Layout& l,
                                                       const std::vector<SweepPoint>& points) {
  std::map<std::size_t, std::vector<std::size_t>> c;
  for (std::size_t n = 0; n < points.size(); ++n) {
    bool first_of_rest = true;  // axes besides x and family at their first value
    for (std::size_t k = 0; k < r.axes.size() && !r.sampled; ++k)
      if (k != *l.x && (!l.family || k != *l.family) && points[n].index[k] != 0)
        first_of_rest = false;
    if (first_of_rest) c[l.family ? points[n].index[*l.family] : 0].push_back(n);
  }
  return c;
}

std::string curve_label(const SweepRequest& r, const Layout& l, std::size_t value) {
  return l.family ? label_of(r.axes[*l.family]) + " = " + r.axes[*l.family].values[value].text : "";
}

Chart solved_chart(const SweepRequest& r, const Layout& l, const std::vector<SweepPoint>& points) {
  const SweepSolve& s = *r.solve;
  Chart c{"solved_" + label_of(s.axis) + "_vs_" + label_of(r.axes[*l.x]),
          std::string("The ") + label_of(s.axis) + " that " + s.target.describe() + " against " +
              label_of(r.axes[*l.x]),
          {label_of(r.axes[*l.x]), r.axes[*l.x].unit},
          {label_of(s.axis), s.axis.unit},
          {},
          "solved to " + axis_value(s.axis, s.tolerance, 3).text + "; gaps: no value in " +
              s.axis.values.front().text + " .. " + s.axis.values.back().text + " meets it"};
  const double unit_si = axis_unit_si(s.axis);
  const auto groups = curves(r, l, points);
  for (const auto& [value, members] : groups) {
    const int colour = static_cast<int>(c.series.size());
    ChartSeries line{curve_label(r, l, value).empty() ? label_of(s.axis) : curve_label(r, l, value),
                     r.sampled ? SeriesStyle::points : SeriesStyle::line,
                     {},
                     {},
                     {},
                     colour};
    ChartSeries band{"marginal", SeriesStyle::band, {}, {}, {}, colour};
    bool banded = false;
    for (std::size_t n : members) {
      const auto& sol = points[n].solution;
      const bool solved = sol && sol->outcome == SweepSolution::Outcome::solved;
      const double x = number_of(r.axes[*l.x].values[points[n].index[*l.x]]);
      line.x.push_back(x);
      line.y.push_back(solved ? sol->value / unit_si : NAN);
      band.x.push_back(x);
      band.y.push_back(solved && sol->marginal_from ? *sol->marginal_from / unit_si : NAN);
      band.y_upper.push_back(solved ? sol->value / unit_si : NAN);
      banded = banded || (solved && sol->marginal_from);
    }
    if (banded && groups.size() == 1 && !r.sampled) c.series.push_back(std::move(band));
    c.series.push_back(std::move(line));
  }
  // --verify: each answer as the full rung judged it there.
  ChartSeries held{"full rung passes", SeriesStyle::points, {}, {}, {}, 2};
  ChartSeries refuted{"full rung does not pass", SeriesStyle::points, {}, {}, {}, 1};
  for (const auto& p : points) {
    const auto& sol = p.solution;
    if (p.rung == "L0" || !p.done || !sol || sol->outcome != SweepSolution::Outcome::solved)
      continue;
    ChartSeries& to = p.verdict == VerdictStatus::pass ? held : refuted;
    to.x.push_back(number_of(r.axes[*l.x].values[p.index[*l.x]]));
    to.y.push_back(sol->value / unit_si);
  }
  for (auto* verified : {&held, &refuted})
    if (!verified->x.empty()) c.series.push_back(std::move(*verified));
  if (c.series.size() > 1 && c.series.front().style == SeriesStyle::band)
    c.note += "; shaded: where the verdict is MARGINAL (inside the band of what it is held to)";
  return c;
}

Chart result_chart(const SweepRequest& r, const Layout& l, const std::vector<SweepPoint>& points,
                   const std::string& key, const Estimate& example) {
  const auto [factor, unit] = display_of(example);
  const SweepAxis& x = r.axes[*l.x];
  Chart c{key + "_vs_" + label_of(x),
          key + " against " + label_of(x),
          {label_of(x), x.unit},
          {key, unit},
          {},
          ""};
  const auto groups = curves(r, l, points);
  int colour = 0;
  bool limits = false;
  for (const auto& [value, members] : groups) {
    ChartSeries line{curve_label(r, l, value).empty() ? key : curve_label(r, l, value),
                     r.sampled ? SeriesStyle::points : SeriesStyle::line,
                     {},
                     {},
                     {},
                     colour};
    ChartSeries band{"band", SeriesStyle::band, {}, {}, {}, colour};
    ChartSeries limit{"limit", SeriesStyle::dashed, {}, {}, {}, colour};
    ++colour;
    for (std::size_t n : members) {
      const SweepPoint& p = points[n];
      const double xv = number_of(x.values[p.index[*l.x]]);
      const Estimate* e = p.done ? find_estimate(p.results, key) : nullptr;
      const bool number = e && e->is_number();
      line.x.push_back(xv);
      line.y.push_back(number ? std::get<double>(e->value) * factor : NAN);
      band.x.push_back(xv);
      band.y.push_back(number && e->low ? *e->low * factor : NAN);
      band.y_upper.push_back(number && e->high ? *e->high * factor : NAN);
      double lim = NAN;
      for (const auto& [q, v] : p.limits)
        if (q == key) lim = v * factor;
      limit.x.push_back(xv);
      limit.y.push_back(lim);
      limits = limits || std::isfinite(lim);
    }
    bool banded = false;
    for (double y : band.y) banded = banded || std::isfinite(y);
    if (groups.size() == 1 && banded && !r.sampled) c.series.push_back(std::move(band));
    c.series.push_back(std::move(line));
    if (limits && !r.sampled) c.series.push_back(std::move(limit));
  }
  c.note = limits ? "dashed: the limit the verdict holds it against" : "";
  return c;
}

Chart verdict_map(const SweepRequest& r, std::size_t kx, std::size_t ky,
                  const std::vector<SweepPoint>& points) {
  const SweepAxis &x = r.axes[kx], &y = r.axes[ky];
  Chart c{"verdict_map",
          "Verdict over " + label_of(x) + " and " + label_of(y),
          {label_of(x), x.unit},
          {label_of(y), y.unit},
          {},
          ""};
  const std::pair<VerdictStatus, int> kinds[] = {
      {VerdictStatus::pass, 2}, {VerdictStatus::marginal, 4}, {VerdictStatus::fail, 1}};
  for (const auto& [status, colour] : kinds) {
    ChartSeries s{to_string(status), SeriesStyle::points, {}, {}, {}, colour};
    for (const auto& p : points)
      if (p.done && p.verdict == status) {
        s.x.push_back(number_of(x.values[p.index[kx]]));
        s.y.push_back(number_of(y.values[p.index[ky]]));
      }
    if (!s.x.empty()) c.series.push_back(std::move(s));
  }
  c.note = "each point of the grid by its verdict; unmarked points were refused by the case";
  return c;
}

}  // namespace

std::vector<Chart> sweep_charts(const SweepRequest& request,
                                const std::vector<SweepPoint>& points) {
  std::vector<Chart> charts;
  const Layout l = layout_of(request);
  if (!l.x || points.empty()) return charts;
  if (request.solve) {
    charts.push_back(solved_chart(request, l, points));
    return charts;
  }
  if (!request.sampled) {
    std::optional<std::size_t> second;
    for (std::size_t k = *l.x + 1; k < request.axes.size() && !second; ++k)
      if (request.axes[k].numeric()) second = k;
    if (second) charts.push_back(verdict_map(request, *l.x, *second, points));
  }
  // The judged results first (they decide the verdict), then the banded ones.
  std::vector<std::pair<std::string, Estimate>> chosen;
  auto consider = [&](bool judged) {
    for (const auto& p : points) {
      if (!p.done) continue;
      for (const auto& [key, e] : p.results) {
        bool is_judged = false;
        for (const auto& [q, v] : p.limits) is_judged = is_judged || q == key;
        const bool wanted = judged ? is_judged : e.high.has_value();
        bool seen = false;
        for (const auto& [k, ex] : chosen) seen = seen || k == key;
        if (e.is_number() && wanted && !seen && chosen.size() < kMaxResultCharts)
          chosen.emplace_back(key, e);
      }
      break;  // the first answered point names the results
    }
  };
  consider(true);
  consider(false);
  for (const auto& [key, e] : chosen) charts.push_back(result_chart(request, l, points, key, e));
  return charts;
}

}  // namespace feedflow
