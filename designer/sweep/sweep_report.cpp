#include "designer/sweep/sweep_report.hpp"

#include "designer/design/case_inputs.hpp"
#include "designer/sweep/sweep_charts.hpp"

namespace feedflow {
namespace {

constexpr std::size_t kRowsShown = 40;

std::string inputs_of(const SweepRequest& r, const SweepPoint& p) {
  std::string s;
  for (std::size_t k = 0; k < r.axes.size(); ++k)
    s += (k ? ", " : "") + r.axes[k].key.substr(r.axes[k].key.find('.') + 1) + " = " +
         r.axes[k].values[p.index[k]].text;
  return s.empty() ? r.parsed.path : s;
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : ", ") + w;
  return s;
}

Estimate row_of(const SweepRequest& r, const SweepPoint& p) {
  Estimate e;
  e.rung = p.rung == "L3" ? Rung::L3 : p.rung == "L2" ? Rung::L2 : Rung::L0;
  if (p.solution && p.solution->outcome == SweepSolution::Outcome::solved) {
    const SweepAxis& a = r.solve->axis;
    const double unit_si = axis_unit_si(a);
    e.value = p.solution->value / unit_si;
    e.unit = a.unit;
    e.low = p.solution->bracket_low / unit_si;
    e.high = p.solution->bracket_high / unit_si;
    e.model =
        std::string("beyond it: ") + to_string(p.solution->beyond_verdict) +
        (p.solution->beyond_governing.empty() ? std::string()
                                              : " (" + joined(p.solution->beyond_governing) + ")");
    return e;
  }
  if (p.solution && p.solution->outcome == SweepSolution::Outcome::met_everywhere) {
    e.value = std::string("met over the whole range");
    return e;
  }
  if (!p.done) {
    e.value = std::string(p.solution ? "never met" : "refused");
    e.model = p.error;
    return e;
  }
  e.value = std::string(to_string(p.verdict));
  if (p.verdict != VerdictStatus::pass && !p.governing.empty())
    e.model = "governing: " + joined(p.governing);
  return e;
}

}  // namespace

DesignRecord sweep_record(const SweepRequest& request, const Case& base,
                          const std::vector<SweepPoint>& points, const SweepTiming& timing,
                          const std::string& command_line) {
  DesignRecord r;
  r.kind = base.kind();
  r.inputs = case_inputs(base);
  std::vector<const SweepAxis*> varied;
  for (const auto& a : request.axes) varied.push_back(&a);
  if (request.solve) varied.push_back(&request.solve->axis);
  for (const SweepAxis* a : varied) {
    const std::string range = a->values.front().text + " .. " + a->values.back().text + " (" +
                              std::to_string(a->values.size()) + " values)";
    bool found = false;
    for (auto& in : r.inputs)
      if (in.key == a->case_key) {
        in.display = "varied: " + range;
        found = true;
      }
    if (!found) r.inputs.push_back({a->case_key, range, "", "varied: " + range, ""});
  }
  r.case_name = std::filesystem::path(request.parsed.path).stem().string() + " sweep";
  r.case_file = request.parsed.path;
  r.description = "feedflow sweep: " + std::to_string(points.size()) + " points" +
                  (request.sampled ? " (Latin hypercube)" : "") +
                  (request.solve ? ", solving for " + request.solve->axis.key +
                                       " where the design " + request.solve->target.describe()
                                 : std::string());
  for (std::size_t n = 0; n < points.size() && n < kRowsShown; ++n)
    r.results.emplace_back(inputs_of(request, points[n]), row_of(request, points[n]));
  if (points.size() > kRowsShown)
    r.assumptions.push_back(std::to_string(points.size() - kRowsShown) +
                            " more points in sweep.csv and sweep.json");
  for (const auto& a : request.axes)
    r.assumptions.push_back("varied " + a.key + ": " + std::to_string(a.values.size()) +
                            " values, " + a.values.front().text + " .. " + a.values.back().text);
  for (const auto& s : request.fixed)
    r.assumptions.push_back("set for every point: " + s.key + " = " + s.value);
  r.charts = sweep_charts(request, points);
  r.verdict.reasons.push_back(
      "note: a sweep of design points; each point's verdict is in the table");
  r.command_line = command_line;
  r.wall_seconds = timing.wall_seconds;
  return r;
}

}  // namespace feedflow
