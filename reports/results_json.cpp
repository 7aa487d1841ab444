#include "reports/results_json.hpp"

#include <sstream>
#include <stdexcept>

namespace feedflow {
namespace {

using json = nlohmann::ordered_json;

json value_json(const std::variant<double, std::string>& v) {
  return std::visit([](const auto& x) { return json(x); }, v);
}

json value_json(const std::variant<double, std::string, std::vector<double>>& v) {
  return std::visit([](const auto& x) { return json(x); }, v);
}

std::variant<double, std::string> value_from(const json& j, const std::string& where) {
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) return j.get<std::string>();
  throw std::invalid_argument(where + ": expected a number or a string");
}

const json& field(const json& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key))
    throw std::invalid_argument(where + ": missing \"" + key + "\"");
  return j.at(key);
}

// inputs are nested objects keyed by the parts of the dotted key.
void put_nested(json& root, const std::string& dotted, json value) {
  json* node = &root;
  std::stringstream parts(dotted);
  std::string part, next;
  std::getline(parts, part, '.');
  while (std::getline(parts, next, '.')) {
    node = &(*node)[part];
    part = next;
  }
  (*node)[part] = std::move(value);
}

void collect_nested(const json& node, const std::string& prefix, const json& units,
                    std::vector<InputValue>& out) {
  for (const auto& [key, value] : node.items()) {
    const std::string dotted = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object()) {
      collect_nested(value, dotted, units, out);
      continue;
    }
    InputValue in;
    in.key = dotted;
    if (value.is_array())
      in.value = value.get<std::vector<double>>();
    else
      std::visit([&](auto v) { in.value = std::move(v); }, value_from(value, "inputs." + dotted));
    if (units.contains(dotted)) in.si_unit = units.at(dotted).get<std::string>();
    in.display = value.is_string() ? value.get<std::string>() : value.dump();
    if (!in.si_unit.empty()) in.display += " " + in.si_unit;
    out.push_back(std::move(in));
  }
}

json axis_json(const ChartAxis& a) {
  return {{"label", a.label}, {"unit", a.unit}, {"logarithmic", a.logarithmic}};
}

ChartAxis axis_from(const json& j, const std::string& where) {
  return {field(j, "label", where).get<std::string>(), field(j, "unit", where).get<std::string>(),
          j.value("logarithmic", false)};
}

json chart_json(const Chart& c) {
  json series = json::array();
  for (const auto& s : c.series) {
    json one = {{"label", s.label}, {"style", to_string(s.style)}, {"x", s.x}, {"y", s.y}};
    if (!s.y_upper.empty()) one["y_upper"] = s.y_upper;
    if (s.colour >= 0) one["colour"] = s.colour;
    series.push_back(std::move(one));
  }
  return {{"id", c.id},       {"title", c.title},   {"x", axis_json(c.x)},
          {"y", axis_json(c.y)}, {"series", series}, {"note", c.note}};
}

Chart chart_from(const json& j) {
  Chart c;
  c.id = field(j, "id", "charts").get<std::string>();
  const std::string where = "charts." + c.id;
  c.title = field(j, "title", where).get<std::string>();
  c.x = axis_from(field(j, "x", where), where + ".x");
  c.y = axis_from(field(j, "y", where), where + ".y");
  c.note = j.value("note", "");
  for (const auto& s : field(j, "series", where)) {
    ChartSeries one;
    one.label = field(s, "label", where).get<std::string>();
    one.style = series_style_from_string(field(s, "style", where).get<std::string>());
    one.x = field(s, "x", where).get<std::vector<double>>();
    one.y = field(s, "y", where).get<std::vector<double>>();
    one.y_upper = s.value("y_upper", std::vector<double>{});
    one.colour = s.value("colour", -1);
    if (one.x.size() != one.y.size() || (!one.y_upper.empty() && one.y_upper.size() != one.x.size()))
      throw std::invalid_argument(where + ": series \"" + one.label + "\" has x and y of different lengths");
    c.series.push_back(std::move(one));
  }
  return c;
}

json optional_number(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

std::optional<double> optional_number_from(const json& j, const char* key) {
  if (!j.contains(key) || j.at(key).is_null()) return std::nullopt;
  return j.at(key).get<double>();
}

json finding_json(const Finding& f) {
  return {{"status", f.status ? to_string(*f.status) : "note"},
          {"quantity", f.quantity},
          {"text", f.text},
          {"value", optional_number(f.value)},
          {"low", optional_number(f.low)},
          {"high", optional_number(f.high)},
          {"limit", optional_number(f.limit)},
          {"unit", f.unit},
          {"display_unit", f.display_unit}};
}

Finding finding_from(const json& j) {
  Finding f;
  const std::string status = field(j, "status", "verdict.findings").get<std::string>();
  if (status != "note") f.status = verdict_status_from_string(status);
  f.quantity = j.value("quantity", "");
  f.text = field(j, "text", "verdict.findings").get<std::string>();
  f.value = optional_number_from(j, "value");
  f.low = optional_number_from(j, "low");
  f.high = optional_number_from(j, "high");
  f.limit = optional_number_from(j, "limit");
  f.unit = j.value("unit", "");
  f.display_unit = j.value("display_unit", "");
  return f;
}

json verdict_json(const Verdict& v) {
  json j = {{"status", to_string(v.status)}, {"reasons", v.reasons}};
  if (!v.findings.empty()) {
    j["findings"] = json::array();
    for (const auto& f : v.findings) j["findings"].push_back(finding_json(f));
  }
  return j;
}

}  // namespace

json to_json(const DesignRecord& r) {
  json j;
  j["feedflow"] = r.feedflow_version;
  j["case"] = {{"name", r.case_name},
               {"kind", to_string(r.kind)},
               {"file", r.case_file},
               {"description", r.description}};
  json inputs = json::object();
  json units = json::object();
  for (const auto& in : r.inputs) {
    put_nested(inputs, in.key, value_json(in.value));
    if (!in.si_unit.empty()) units[in.key] = in.si_unit;
  }
  json sources = json::object();
  json display = json::object();  // as a person reads them ("30 deg"), for a report rendered again
  for (const auto& in : r.inputs) {
    if (!in.source.empty()) sources[in.key] = in.source;
    if (!in.display.empty()) display[in.key] = in.display;
  }
  j["inputs"] = std::move(inputs);
  j["input_units"] = std::move(units);
  j["input_display"] = std::move(display);
  j["input_sources"] = std::move(sources);
  json results = json::object();
  for (const auto& [name, e] : r.results) {
    json q = {{"value", value_json(e.value)},
              {"unit", e.unit},
              {"model", e.model},
              {"rung", to_string(e.rung)}};
    if (!e.display_unit.empty()) q["display_unit"] = e.display_unit;
    q["low"] = e.low ? json(*e.low) : json(nullptr);
    q["high"] = e.high ? json(*e.high) : json(nullptr);
    results[name] = std::move(q);
  }
  j["results"] = std::move(results);
  j["verdict"] = verdict_json(r.verdict);
  j["charts"] = json::array();
  for (const auto& c : r.charts) j["charts"].push_back(chart_json(c));
  j["assumptions"] = r.assumptions;
  j["provenance"] = {{"command_line", r.command_line}};
  if (!r.simulation_runs.empty()) j["provenance"]["simulation_runs"] = r.simulation_runs;
  j["timing"] = {{"wall_s", r.wall_seconds}};
  if (!r.performance.empty()) {
    j["performance"] = json::array();
    for (const auto& p : r.performance) {
      json block = {{"title", p.title},
                    {"wall_s", p.wall_seconds},
                    {"figures", json::object()},
                    {"phases_s", json::object()}};
      for (const auto& [name, value] : p.figures) block["figures"][name] = value;
      for (const auto& [name, seconds] : p.phases) block["phases_s"][name] = seconds;
      j["performance"].push_back(std::move(block));
    }
  }
  return j;
}

Estimates estimates_from_json(const json& results) {
  Estimates out;
  try {
    for (const auto& [name, q] : results.items()) {
      const std::string where = "results." + name;
      Estimate e;
      e.value = value_from(field(q, "value", where), where + ".value");
      e.unit = field(q, "unit", where).get<std::string>();
      if (q.contains("low") && !q.at("low").is_null()) e.low = q.at("low").get<double>();
      if (q.contains("high") && !q.at("high").is_null()) e.high = q.at("high").get<double>();
      e.model = field(q, "model", where).get<std::string>();
      e.rung = rung_from_string(field(q, "rung", where).get<std::string>());
      e.display_unit = q.value("display_unit", "");
      out.emplace_back(name, std::move(e));
    }
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("results JSON: ") + e.what());
  }
  return out;
}

DesignRecord design_record_from_json(const json& j) {
  DesignRecord r;
  try {
    r.feedflow_version = field(j, "feedflow", "results").get<std::string>();
    const json& c = field(j, "case", "results");
    r.case_name = field(c, "name", "case").get<std::string>();
    r.kind = equipment_kind_from_string(field(c, "kind", "case").get<std::string>());
    r.case_file = field(c, "file", "case").get<std::string>();
    r.description = c.value("description", "");
    const json units = j.value("input_units", json::object());
    collect_nested(field(j, "inputs", "results"), "", units, r.inputs);
    r.results = estimates_from_json(field(j, "results", "results"));
    const json& v = field(j, "verdict", "results");
    r.verdict.status = verdict_status_from_string(field(v, "status", "verdict").get<std::string>());
    r.verdict.reasons = field(v, "reasons", "verdict").get<std::vector<std::string>>();
    for (const auto& f : v.value("findings", json::array())) r.verdict.findings.push_back(finding_from(f));
    r.wall_seconds = field(field(j, "timing", "results"), "wall_s", "timing").get<double>();
    const json sources = j.value("input_sources", json::object());
    const json display = j.value("input_display", json::object());
    for (auto& in : r.inputs) {
      if (sources.contains(in.key)) in.source = sources.at(in.key).get<std::string>();
      if (display.contains(in.key)) in.display = display.at(in.key).get<std::string>();
    }
    for (const auto& c : j.value("charts", json::array())) r.charts.push_back(chart_from(c));
    r.assumptions = j.value("assumptions", std::vector<std::string>{});
    for (const auto& b : j.value("performance", json::array())) {
      PerformanceBlock p;
      p.title = b.value("title", "");
      p.wall_seconds = b.value("wall_s", 0.0);
      const json figures = b.value("figures", json::object()),
                 phases = b.value("phases_s", json::object());
      for (const auto& [name, value] : figures.items())
        p.figures.emplace_back(name, value.get<std::string>());
      for (const auto& [name, seconds] : phases.items())
        p.phases.emplace_back(name, seconds.get<double>());
      r.performance.push_back(std::move(p));
    }
    if (j.contains("provenance")) {
      r.command_line = j.at("provenance").value("command_line", "");
      r.simulation_runs = j.at("provenance").value("simulation_runs", std::vector<std::string>{});
    }
  } catch (const json::exception& e) {
    throw std::invalid_argument(std::string("results JSON: ") + e.what());
  }
  return r;
}

}  // namespace feedflow
