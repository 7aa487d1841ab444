#include "designer/sweep/sweep_output.hpp"

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

struct ResultColumn {
  std::string key, unit;
  bool numeric = true;
};

// The result keys in the order they first appear, with their units.
std::vector<ResultColumn> result_columns(const std::vector<SweepPoint>& points) {
  std::vector<ResultColumn> columns;
  for (const auto& p : points)
    for (const auto& [key, e] : p.results) {
      bool seen = false;
      for (const auto& c : columns) seen = seen || c.key == key;
      if (!seen) columns.push_back({key, e.unit, e.is_number()});
    }
  return columns;
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string number_text(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

// An axis value as shown: its number in the axis unit, or its word.
std::string shown(const SweepAxis& axis, std::size_t i) { return axis.values[i].text; }

std::string in_words_range(const SweepAxis& axis, const SweepSolution& s) {
  return axis_value(axis, s.bracket_low, 6).text + " .. " +
         axis_value(axis, s.bracket_high, 6).text;
}

// A solved axis's SI value as a number in the axis unit.
double in_axis_unit(const SweepAxis& axis, double si) {
  return std::stod(axis_value(axis, si).text);
}

const char* outcome_name(SweepSolution::Outcome o) {
  switch (o) {
    case SweepSolution::Outcome::solved: return "solved";
    case SweepSolution::Outcome::met_everywhere: return "met everywhere";
    case SweepSolution::Outcome::never_met: return "never met";
  }
  return "";
}

// done; refused (the case refuses the values); failed (a simulation could not answer); not met.
std::string point_status(const SweepPoint& p) {
  if (p.solution && p.solution->outcome == SweepSolution::Outcome::never_met) return "not met";
  if (p.done) return "done";
  return p.rung == "L0" ? "refused" : "failed";
}

nlohmann::ordered_json solution_json(const SweepSolve& solve, const SweepSolution& s) {
  const SweepAxis& a = solve.axis;
  nlohmann::ordered_json j{{"outcome", outcome_name(s.outcome)}};
  if (s.outcome == SweepSolution::Outcome::solved) {
    j["value"] = in_axis_unit(a, s.value);
    j["text"] = s.text;
    j["value_si"] = s.value;
    j["meets"] = s.smallest ? "at and above" : "at and below";
    if (s.marginal_from) j["marginal_from"] = in_axis_unit(a, *s.marginal_from);
  }
  if (s.outcome != SweepSolution::Outcome::never_met)
    j["bracket"] = {in_axis_unit(a, s.bracket_low), in_axis_unit(a, s.bracket_high)};
  if (!s.beyond_text.empty())
    j["beyond"] = {{"value", s.beyond_text},
                   {"verdict", to_string(s.beyond_verdict)},
                   {"governing", s.beyond_governing},
                   {"reason", s.beyond_reason}};
  j["evaluations"] = s.evaluations;
  j["crossings"] = s.crossings;
  return j;
}

// "smallest hopper.outlet_width that passes: 37.25 mm (beyond: 37.2 mm: fail,
// critical_outlet_width)"
std::string solution_words(const SweepSolve& solve, const SweepPoint& p) {
  const SweepSolution& s = *p.solution;
  switch (s.outcome) {
    case SweepSolution::Outcome::solved: {
      std::string line = std::string(s.smallest ? "smallest " : "largest ") + solve.axis.key +
                         " that " + solve.target.describe() + ": " + s.text + " (beyond, " +
                         s.beyond_text + ": " + to_string(s.beyond_verdict);
      for (const auto& g : s.beyond_governing) line += ", " + g;
      line += ")";
      if (s.crossings > 1)
        line += "; the condition changes " + std::to_string(s.crossings) +
                " times along the scan, the first is solved";
      return line;
    }
    case SweepSolution::Outcome::met_everywhere:
      return solve.axis.key + " " + solve.target.describe() + " over the whole range " +
             in_words_range(solve.axis, s) + ": the boundary is beyond it";
    case SweepSolution::Outcome::never_met: return p.error;
  }
  return "";
}

}  // namespace

std::string sweep_json(const SweepRequest& request, const std::vector<SweepPoint>& points,
                       const SweepTiming& timing, const std::string& command_line) {
  nlohmann::ordered_json j;
  j["feedflow_sweep"] = 1;
  j["case"] = request.parsed.path;
  j["command_line"] = command_line;
  nlohmann::ordered_json fixed = nlohmann::ordered_json::array();
  for (const auto& s : request.fixed) fixed.push_back(s.key + "=" + s.value);
  j["fixed"] = fixed;
  nlohmann::ordered_json axes = nlohmann::ordered_json::array();
  for (const auto& a : request.axes) {
    nlohmann::ordered_json axis{{"key", a.key}, {"unit", a.unit}};
    nlohmann::ordered_json values = nlohmann::ordered_json::array();
    for (const auto& v : a.values) values.push_back(v.text);
    axis["values"] = values;
    if (a.numeric()) {
      nlohmann::ordered_json si = nlohmann::ordered_json::array();
      for (const auto& v : a.values) si.push_back(*v.si);
      axis["values_si"] = si;
    }
    axes.push_back(axis);
  }
  j["vary"] = axes;
  j["sample"] = request.sampled ? "latin hypercube" : "grid";
  if (request.solve) {
    const SweepSolve& solve = *request.solve;
    nlohmann::ordered_json scan = nlohmann::ordered_json::array();
    for (const auto& v : solve.axis.values) scan.push_back(v.text);
    j["solve"] = {{"key", solve.axis.key},
                  {"unit", solve.axis.unit},
                  {"target", solve.target.text},
                  {"condition", solve.target.describe()},
                  {"tolerance", in_axis_unit(solve.axis, solve.tolerance)},
                  {"scan", scan}};
  }
  // Every point's results as arrays aligned with "results" (a key and its unit each): a sweep of
  // thousands of points stays a file of a few megabytes.
  const auto columns = result_columns(points);
  nlohmann::ordered_json header = nlohmann::ordered_json::array();
  for (const auto& c : columns) header.push_back({{"key", c.key}, {"unit", c.unit}});
  j["results"] = header;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  std::map<std::string, int> counts;
  for (const auto& p : points) {
    nlohmann::ordered_json row;
    nlohmann::ordered_json inputs = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < request.axes.size(); ++k)
      inputs.push_back(request.axes[k].values[p.index[k]].text);
    row["inputs"] = inputs;
    row["status"] = point_status(p);
    row["rung"] = p.rung;
    if (!p.folder.empty()) row["folder"] = p.folder.string();
    if (p.solution) row["solution"] = solution_json(*request.solve, *p.solution);
    if (!p.done) {
      row["reason"] = p.error;
      ++counts[point_status(p)];
    } else {
      row["verdict"] = to_string(p.verdict);
      ++counts[to_string(p.verdict)];
      row["governing"] = p.governing;
      nlohmann::ordered_json value = nlohmann::ordered_json::array(), low = value, high = value;
      for (const auto& column : columns) {
        const Estimate* e = find_estimate(p.results, column.key);
        if (!e) {
          value.push_back(nullptr);
        } else if (e->is_number()) {
          value.push_back(std::get<double>(e->value));
        } else {
          value.push_back(std::get<std::string>(e->value));
        }
        low.push_back(e && e->low ? nlohmann::ordered_json(*e->low)
                                  : nlohmann::ordered_json(nullptr));
        high.push_back(e && e->high ? nlohmann::ordered_json(*e->high)
                                    : nlohmann::ordered_json(nullptr));
      }
      row["values"] = value;
      row["low"] = low;
      row["high"] = high;
    }
    row["wall_s"] = p.wall_seconds;
    rows.push_back(std::move(row));
  }
  j["counts"] = counts;
  j["timing"] = {
      {"wall_s", timing.wall_seconds},
      {"points_s", timing.point_seconds},
      {"threads", timing.threads},
      {"ranks", timing.ranks},
      {"points_run", timing.made},
      {"points_read_back", timing.read_back},
      {"points_per_s", timing.point_seconds > 0.0 ? points.size() / timing.point_seconds : 0.0}};
  j["points"] = rows;
  return j.dump() + "\n";
}

std::string sweep_csv(const SweepRequest& request, const std::vector<SweepPoint>& points) {
  const auto columns = result_columns(points);
  std::ostringstream out;
  out << "point";
  for (const auto& a : request.axes)
    out << ',' << csv_field(a.unit.empty() ? a.key : a.key + " [" + a.unit + "]");
  if (request.solve) {
    const SweepAxis& a = request.solve->axis;
    out << ',' << csv_field(a.key + " solved" + (a.unit.empty() ? "" : " [" + a.unit + "]"))
        << ",outcome,meets,beyond governing,evaluations";
  }
  out << ",rung,status,verdict,governing";
  for (const auto& c : columns) {
    const std::string u = c.unit.empty() ? "" : " [" + c.unit + "]";
    out << ',' << csv_field(c.key + u);
    if (c.numeric)
      out << ',' << csv_field(c.key + " low" + u) << ',' << csv_field(c.key + " high" + u);
  }
  out << ",wall time [s],reason\n";
  for (std::size_t n = 0; n < points.size(); ++n) {
    const SweepPoint& p = points[n];
    out << n;
    for (std::size_t k = 0; k < request.axes.size(); ++k) {
      const SweepAxis& a = request.axes[k];
      const SweepValue& v = a.values[p.index[k]];
      // The number in the axis unit (the text without it), or the word.
      std::string cell = v.text;
      if (!a.unit.empty() && cell.size() > a.unit.size() + 1)
        cell.resize(cell.size() - a.unit.size() - 1);
      out << ',' << csv_field(cell);
    }
    if (request.solve) {
      const SweepSolution& s = *p.solution;
      const bool solved = s.outcome == SweepSolution::Outcome::solved;
      std::string beyond;
      for (const auto& g : s.beyond_governing) beyond += (beyond.empty() ? "" : " ") + g;
      out << ',' << (solved ? number_text(in_axis_unit(request.solve->axis, s.value)) : "") << ','
          << outcome_name(s.outcome) << ',' << (solved ? (s.smallest ? "above" : "below") : "")
          << ',' << csv_field(beyond) << ',' << s.evaluations;
    }
    std::string governing;
    for (const auto& g : p.governing) governing += (governing.empty() ? "" : " ") + g;
    out << ',' << p.rung << ',' << point_status(p) << ',' << (p.done ? to_string(p.verdict) : "")
        << ',' << csv_field(governing);
    for (const auto& c : columns) {
      const Estimate* e = p.done ? find_estimate(p.results, c.key) : nullptr;
      out << ',';
      if (e)
        out << (e->is_number() ? number_text(std::get<double>(e->value))
                               : csv_field(std::get<std::string>(e->value)));
      if (!c.numeric) continue;
      out << ',' << (e && e->low ? number_text(*e->low) : "") << ','
          << (e && e->high ? number_text(*e->high) : "");
    }
    out << ',' << number_text(p.wall_seconds) << ',' << csv_field(p.error) << '\n';
  }
  return out.str();
}

std::string sweep_summary(const SweepRequest& request, const std::vector<SweepPoint>& points,
                          const SweepTiming& timing, std::size_t rows) {
  std::ostringstream out;
  out << "feedflow sweep: " << request.parsed.path << "\n";
  for (const auto& a : request.axes)
    out << "  vary " << a.key << ": " << a.values.size() << " values, " << a.values.front().text
        << " .. " << a.values.back().text << "\n";
  if (request.solve)
    out << "  solve for " << request.solve->axis.key << " where the design "
        << request.solve->target.describe() << ", scanned " << request.solve->axis.values.size()
        << " values " << request.solve->axis.values.front().text << " .. "
        << request.solve->axis.values.back().text << ", to "
        << axis_value(request.solve->axis, request.solve->tolerance, 4).text << "\n";
  std::map<std::string, int> counts;
  for (const auto& p : points)
    ++counts[p.solution ? outcome_name(p.solution->outcome)
             : p.done   ? to_string(p.verdict)
                        : point_status(p)];
  out << "\n" << points.size() << " points:";
  for (const auto& [what, n] : counts) out << " " << what << " x" << n;
  out << "\n";
  const std::size_t listed = std::min(rows, points.size());
  out << "\n";
  for (std::size_t n = 0; n < listed; ++n) {
    const SweepPoint& p = points[n];
    std::string line = "  ";
    for (std::size_t k = 0; k < request.axes.size(); ++k)
      line += (k ? ", " : "") + request.axes[k].key + " = " + shown(request.axes[k], p.index[k]);
    if (p.solution) {
      line += (line.size() > 2 ? ": " : "") + solution_words(*request.solve, p);
      if (p.rung != "L0" && p.solution->outcome == SweepSolution::Outcome::solved)
        line += p.done ? "; verified there on " + p.rung + ": " + to_string(p.verdict)
                       : "; not verified: " + p.error;
    } else if (!p.done) {
      line += ": " + point_status(p) + ": " + p.error;
    } else {
      line += ": " + std::string(to_string(p.verdict));
      if (!p.governing.empty() && p.verdict != VerdictStatus::pass) {
        line += " (";
        for (std::size_t g = 0; g < p.governing.size(); ++g)
          line += (g ? ", " : "") + p.governing[g];
        line += ")";
      }
    }
    out << line << "\n";
  }
  if (listed < points.size()) out << "  ... " << points.size() - listed << " more in sweep.csv\n";
  std::size_t checks = 0;  // design checks made: a solve makes tens per point
  for (const auto& p : points) checks += p.solution ? p.solution->evaluations : 1;
  const double per_second = timing.point_seconds > 0 ? 1.0 / timing.point_seconds : 0.0;
  out << "\nWall time: "
      << format_quantity(timing.wall_seconds, timing.wall_seconds < 1 ? "ms" : "s") << " on "
      << timing.ranks << (timing.ranks == 1 ? " rank x " : " ranks x ") << timing.threads
      << (timing.threads == 1 ? " thread" : " threads") << "; the points "
      << format_quantity(timing.point_seconds, timing.point_seconds < 1 ? "ms" : "s") << " ("
      << format_number(points.size() * per_second, 3) << " points/s";
  if (request.solve)
    out << ", " << checks << " design checks, " << format_number(checks * per_second, 3) << "/s";
  out << ")\n";
  if (timing.made + timing.read_back > 0)
    out << "Simulated points: " << timing.made << " run now, " << timing.read_back
        << " read back from an earlier run; " << timing.ranks
        << (timing.ranks == 1 ? " rank" : " ranks") << "\n";
  return out.str();
}

}  // namespace feedflow
