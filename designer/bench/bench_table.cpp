#include "designer/bench/bench_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "models/numerics/pareto_front.hpp"
#include "models/numerics/richardson.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::optional<double> number_at(const nlohmann::ordered_json& e, const char* key) {
  if (!e.contains(key) || !e[key].is_number()) return std::nullopt;
  return e[key].get<double>();
}

BenchAnswer answer_of(const BenchPoint& p, const std::map<std::string, BenchRun>& runs) {
  BenchAnswer a;
  a.point = &p;
  const auto it = runs.find(point_id(p));
  if (it == runs.end()) {
    a.label = "not run";
    return a;
  }
  a.run = &it->second;
  if (!a.run->done()) {
    a.label = a.run->status;
    return a;
  }
  const auto& results = a.run->results;
  if (!results.contains(p.quantity)) {
    a.label = "no " + p.quantity + " in the results";
    return a;
  }
  const auto& e = results[p.quantity];
  // A verification that did not answer on its rung (a search cut short) left the reduced answer
  // in place: it is no answer of the point's.
  if (!p.verify.empty() && e.value("rung", p.rung) != p.rung) {
    a.label =
        "not answered on " + p.rung + " (" + p.quantity + " stays " + e.value("rung", "") + ")";
    return a;
  }
  if (p.label_rule && e.at("value").is_number()) {  // a number read as the question's label
    a.label = e["value"].get<double>() > p.label_rule->threshold ? p.label_rule->above : p.label_rule->below;
    return a;
  }
  if (e.at("value").is_number()) {
    a.value = e["value"].get<double>();
    a.low = number_at(e, "low");
    a.high = number_at(e, "high");
  } else {
    a.label = e["value"].get<std::string>();
  }
  a.unit = e.value("unit", "");
  if (p.interval_key == p.quantity && a.low && a.high)
    a.interval = 0.5 * (*a.high - *a.low);
  else if (!p.interval_key.empty() && results.contains(p.interval_key))
    a.interval = number_at(results[p.interval_key], "value");
  if (!p.rest_key.empty() && results.contains(p.rest_key)) {
    const auto& rest = results[p.rest_key].at("value");
    a.at_rest = rest.is_string() && rest.get<std::string>().rfind("yes", 0) == 0;
  }
  return a;
}

// An answer that can enter a reference: a value (or label) from a run that ended as it must.
bool settled(const BenchAnswer& a) { return a.at_rest.value_or(true); }

std::string millimetres(double metres) { return format_number(metres * 1e3, 3); }

// A CEL estimate's error bar with the finest level's statistical interval added in quadrature
// (a discretisation error and the time average's noise are independent; levels closer than
// their noise make a Richardson bar that is the noise's, not the grid's).
void add_finest_interval(BenchReference& r, const BenchAnswer& finest) {
  if (!finest.interval) return;
  r.error_bar = std::hypot(r.error_bar.value_or(0.0), *finest.interval);
  r.source += "; error bar with the finest level's 95 % interval +-" +
              format_number(*finest.interval, 2) + " " + finest.unit + " in quadrature";
}

// The CEL refinement series' estimate: Richardson on the finest three levels, two levels with
// the donor-cell remap's formal order 1, or the one level there is.
std::optional<BenchReference> cel_reference(const std::vector<BenchAnswer>& answers, const BenchQuestion& q) {
  const bool categorical = q.categorical;
  std::vector<const BenchAnswer*> levels;
  for (const auto& a : answers)
    if (a.point->role == ReferenceRole::cel_refinement && a.point->cell_size && settled(a) &&
        (a.value || (categorical && a.run && a.run->done() && !a.label.empty() &&
                     a.label.rfind("no ", 0) != 0)))
      levels.push_back(&a);
  if (levels.empty()) return std::nullopt;
  std::sort(levels.begin(), levels.end(),
            [](const BenchAnswer* x, const BenchAnswer* y) { return *x->point->cell_size > *y->point->cell_size; });
  BenchReference r;
  r.unit = levels.back()->unit;
  if (categorical) {
    r.label = levels.back()->label;
    r.source = "CEL at " + millimetres(*levels.back()->point->cell_size) + " mm cells (the finest run)";
    r.only_run = point_id(*levels.back()->point);
    return r;
  }
  const std::size_t n = levels.size();
  if (n >= 3) {
    const BenchAnswer *a = levels[n - 3], *b = levels[n - 2], *c = levels[n - 1];
    try {
      const RichardsonEstimate e = richardson({*a->point->cell_size, *b->point->cell_size, *c->point->cell_size},
                                              {*a->value, *b->value, *c->value});
      r.value = e.value;
      r.error_bar = e.error_bar;
      r.order = e.order;
      if (!e.order) r.only_run = point_id(*c->point);  // no order: the finest run is the value
      r.source = "CEL Richardson (" + millimetres(*a->point->cell_size) + ", " +
                 millimetres(*b->point->cell_size) + ", " + millimetres(*c->point->cell_size) +
                 " mm; " +
                 (e.order ? "observed order " + format_number(*e.order, 3) +
                                (e.asymptotic ? "" : ", outside the asymptotic range")
                  : e.diverging
                      ? std::string("no observed order: diverging, each refinement moves it more")
                      : std::string("no observed order: not converging monotonically"));
      add_finest_interval(r, *c);
      r.source += ")";
      return r;
    } catch (const std::invalid_argument&) {  // not one ratio: the two finest
    }
  }
  if (n >= 2) {
    const BenchAnswer *b = levels[n - 2], *c = levels[n - 1];
    const RichardsonEstimate e = richardson_two_levels({*b->point->cell_size, *c->point->cell_size},
                                                       {*b->value, *c->value}, q.two_level_order.value_or(1.0));
    r.value = e.value;
    r.error_bar = e.error_bar;
    r.source = "CEL two levels (" + millimetres(*b->point->cell_size) + ", " +
               millimetres(*c->point->cell_size) + " mm; " +
               (q.two_level_order ? "order " + format_number(*q.two_level_order, 3) + " " +
                                        q.two_level_order_source
                                  : std::string("formal order 1")) +
               ", safety 3";
    add_finest_interval(r, *c);
    r.source += ")";
    return r;
  }
  r.value = levels.back()->value;
  r.source = "CEL at " + millimetres(*levels.back()->point->cell_size) + " mm cells (one level: no error bar)";
  r.only_run = point_id(*levels.back()->point);
  return r;
}

std::optional<BenchReference> dem_reference(const std::vector<BenchAnswer>& answers, bool categorical) {
  for (const auto& a : answers) {
    if (a.point->role != ReferenceRole::dem_reference || !a.run || !a.run->done() || !settled(a))
      continue;
    BenchReference r;
    r.unit = a.unit;
    r.source = a.point->setting + " at the seed's resolution";
    r.only_run = point_id(*a.point);
    if (categorical && !a.value && a.label.rfind("no ", 0) != 0) {
      r.label = a.label;
      return r;
    }
    if (!categorical && a.value) {
      r.value = a.value;
      if (a.interval) {
        r.error_bar = a.interval;
        r.source += " (error bar: its 95 % interval)";
      } else if (a.low && a.high) {
        r.error_bar = 0.5 * (*a.high - *a.low);
        r.source += " (error bar: half its band)";
      }
      return r;
    }
  }
  return std::nullopt;
}

std::string agreement(const BenchReference& cel, const BenchReference& dem, bool categorical) {
  if (categorical)
    return cel.label == dem.label ? "CEL and DEM agree (" + cel.label + ")"
                                  : "CEL and DEM disagree: CEL " + cel.label + ", DEM " + dem.label;
  const double gap = std::abs(*cel.value - *dem.value);
  const double allowed = cel.error_bar.value_or(0.0) + dem.error_bar.value_or(0.0);
  const std::string both = "CEL " + format_number(*cel.value, 4) + " +- " + format_number(cel.error_bar.value_or(0.0), 3) +
                           ", DEM " + format_number(*dem.value, 4) + " +- " + format_number(dem.error_bar.value_or(0.0), 3) +
                           " " + cel.unit;
  return (gap <= allowed ? "CEL and DEM agree within their error bars (" : "CEL and DEM disagree (") + both + ")";
}

}  // namespace

BenchQuestionTable tabulate(const BenchQuestion& q, const std::map<std::string, BenchRun>& runs) {
  BenchQuestionTable t;
  t.question = &q;
  for (const auto& p : q.points) t.answers.push_back(answer_of(p, runs));
  const auto cel = cel_reference(t.answers, q);
  const auto dem = dem_reference(t.answers, q.categorical);
  if (cel) t.reference = *cel;
  else if (dem) t.reference = *dem;
  if (cel && dem) t.reference.agreement = agreement(*cel, *dem, q.categorical);

  std::vector<double> cost, error;
  for (auto& a : t.answers) {
    if (point_id(*a.point) == t.reference.only_run) {  // the reference itself: no error to show
      cost.push_back(NAN);
      error.push_back(NAN);
      continue;
    }
    if (q.categorical && !t.reference.label.empty() && a.run && a.run->done() && !a.value && a.label.rfind("no ", 0) != 0)
      a.error = a.label == t.reference.label ? 0.0 : 1.0;
    if (!q.categorical && t.reference.value && a.value) {
      const double ref = *t.reference.value;
      a.error = ref != 0.0 ? std::abs(*a.value - ref) / std::abs(ref) : std::abs(*a.value);
      if (a.low && a.high) a.band_holds_reference = *a.low <= ref && ref <= *a.high;
    }
    const bool ranked = a.error && a.run && settled(a);
    cost.push_back(ranked ? a.run->wall_seconds : NAN);
    error.push_back(ranked ? *a.error : NAN);
  }
  const std::vector<bool> front = pareto_front(cost, error);
  for (std::size_t k = 0; k < t.answers.size(); ++k) t.answers[k].pareto = front[k];
  return t;
}

namespace {

nlohmann::ordered_json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json bench_json(const std::vector<BenchQuestionTable>& tables) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& t : tables) {
    const BenchQuestion& q = *t.question;
    nlohmann::ordered_json jq;
    jq["id"] = q.id;
    jq["title"] = q.title;
    jq["case"] = q.case_file;
    jq["sets"] = q.sets;
    jq["kind"] = q.categorical ? "label" : "number";
    nlohmann::ordered_json ref;
    ref["source"] = t.reference.source;
    if (q.categorical) ref["label"] = t.reference.label;
    else {
      ref["value"] = optional_number(t.reference.value);
      ref["error_bar"] = optional_number(t.reference.error_bar);
      ref["order"] = optional_number(t.reference.order);
      ref["unit"] = t.reference.unit;
    }
    ref["agreement"] = t.reference.agreement;
    jq["reference"] = ref;
    jq["answers"] = nlohmann::ordered_json::array();
    for (const auto& a : t.answers) {
      nlohmann::ordered_json ja;
      ja["rung"] = a.point->rung;
      ja["setting"] = a.point->setting;
      ja["quantity"] = a.point->quantity;
      ja["quick"] = a.point->quick;
      if (!a.point->resolution.empty()) ja["resolution"] = a.point->resolution;
      ja["in_reference"] = a.point->role != ReferenceRole::none;
      ja["invocation"] = bench_invocation(q, *a.point);
      ja["status"] = a.run ? a.run->status : std::string("not run");
      if (a.value) {
        ja["value"] = *a.value;
        ja["low"] = optional_number(a.low);
        ja["high"] = optional_number(a.high);
        if (a.interval) ja["interval"] = *a.interval;
        ja["unit"] = a.unit;
      } else {
        ja["label"] = a.label;
      }
      if (a.at_rest) ja["at_rest"] = *a.at_rest;
      ja["error"] = optional_number(a.error);
      ja["error_unit"] = q.categorical ? "wrong (1) or right (0)" : "relative";
      ja["band_holds_reference"] = a.band_holds_reference ? nlohmann::ordered_json(*a.band_holds_reference)
                                                          : nlohmann::ordered_json(nullptr);
      ja["pareto_front"] = a.pareto;
      ja["wall_seconds"] = a.run ? nlohmann::ordered_json(a.run->wall_seconds) : nlohmann::ordered_json(nullptr);
      ja["cores"] = a.run ? nlohmann::ordered_json(a.run->cores) : nlohmann::ordered_json(nullptr);
      if (a.run && !a.run->commit.empty()) ja["commit"] = a.run->commit;
      jq["answers"].push_back(ja);
    }
    out.push_back(jq);
  }
  return out;
}

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string csv_number(const std::optional<double>& v) {
  if (!v) return "";
  std::ostringstream o;
  o.precision(10);
  o << *v;
  return o.str();
}

}  // namespace

std::string bench_csv(const std::vector<BenchQuestionTable>& tables) {
  std::string s =
      "question,rung,setting,resolution,in_reference,quantity,value,low,high,interval,unit,"
      "reference,reference_error_bar,error,band_holds_reference,pareto_front,wall_time_s,cores,"
      "status,invocation\n";
  for (const auto& t : tables)
    for (const auto& a : t.answers) {
      const BenchQuestion& q = *t.question;
      std::vector<std::string> f = {
          q.id,
          a.point->rung,
          csv_field(a.point->setting),
          csv_field(a.point->resolution),
          a.point->role != ReferenceRole::none ? "yes" : "no",
          a.point->quantity,
          a.value ? csv_number(a.value) : csv_field(a.label),
          csv_number(a.low),
          csv_number(a.high),
          csv_number(a.interval),
          csv_field(a.unit),
          q.categorical ? csv_field(t.reference.label) : csv_number(t.reference.value),
          csv_number(t.reference.error_bar),
          csv_number(a.error),
          a.band_holds_reference ? (*a.band_holds_reference ? "yes" : "no") : "",
          a.pareto ? "yes" : "no",
          a.run ? csv_number(a.run->wall_seconds) : "",
          a.run ? std::to_string(a.run->cores) : "",
          csv_field(a.run ? a.run->status + (settled(a) ? "" : " (not at rest: an upper bound)")
                          : "not run"),
          csv_field(bench_invocation(q, *a.point))};
      for (std::size_t k = 0; k < f.size(); ++k) s += (k ? "," : "") + f[k];
      s += "\n";
    }
  return s;
}

std::optional<Chart> error_against_time_chart(const BenchQuestionTable& t) {
  if (t.question->categorical || !t.reference.value) return std::nullopt;
  Chart chart{"bench_" + t.question->id, t.question->title + ": error against wall time",
              {"wall time", "s", true}, {"error against the reference", "%", true}, {}, ""};
  std::map<std::string, ChartSeries> by_rung;
  std::vector<std::pair<double, double>> front;
  std::size_t exact = 0;
  for (const auto& a : t.answers) {
    if (!a.error || !a.run) continue;
    if (!(*a.error > 0.0) || !(a.run->wall_seconds > 0.0)) {
      ++exact;
      continue;
    }
    ChartSeries& s = by_rung[a.point->rung];
    s.label = a.point->rung;
    s.style = SeriesStyle::points;
    s.x.push_back(a.run->wall_seconds);
    s.y.push_back(100.0 * *a.error);
    if (a.pareto) front.emplace_back(a.run->wall_seconds, 100.0 * *a.error);
  }
  if (by_rung.empty()) return std::nullopt;
  double fastest = INFINITY, slowest = 0.0;
  for (auto& [rung, s] : by_rung) {
    for (double x : s.x) {
      fastest = std::min(fastest, x);
      slowest = std::max(slowest, x);
    }
    chart.series.push_back(std::move(s));
  }
  // The reference's own error bar: an error below it is within the reference's uncertainty.
  if (t.reference.error_bar && *t.reference.error_bar > 0.0 && *t.reference.value != 0.0) {
    const double bar = 100.0 * *t.reference.error_bar / std::abs(*t.reference.value);
    chart.series.push_back({"reference's error bar (errors below it unresolved)",
                            SeriesStyle::line,
                            {fastest, slowest},
                            {bar, bar},
                            {}});
  }
  std::sort(front.begin(), front.end());
  ChartSeries line{"Pareto front", SeriesStyle::dashed, {}, {}, {}};
  for (const auto& [x, y] : front) {
    line.x.push_back(x);
    line.y.push_back(y);
  }
  chart.series.push_back(std::move(line));
  chart.note = "reference: " + t.reference.source;
  if (exact > 0) chart.note += "; " + std::to_string(exact) + " point(s) with zero error or time not drawn";
  return chart;
}

}  // namespace feedflow
