#include "designer/bench/measured_bench.hpp"

#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace feedflow {
namespace {

std::optional<double> number(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

MeasuredAnswer answer_of(const nlohmann::json& a) {
  MeasuredAnswer m;
  m.rung = a.at("rung").get<std::string>();
  m.setting = a.at("setting").get<std::string>();
  m.resolution = a.value("resolution", "");
  m.status = a.at("status").get<std::string>();
  m.invocation = a.value("invocation", "");
  m.value = number(a, "value");
  if (a.contains("label") && a["label"].is_string()) m.label = a["label"].get<std::string>();
  m.error = number(a, "error");
  m.wall_seconds = number(a, "wall_seconds");
  if (a.contains("cores") && a["cores"].is_number()) m.cores = a["cores"].get<int>();
  m.in_reference = a.value("in_reference", false);
  m.at_rest = a.value("at_rest", true);
  return m;
}

}  // namespace

const MeasuredQuestion* MeasuredBench::find(std::string_view id) const {
  for (const auto& q : questions)
    if (q.id == id) return &q;
  return nullptr;
}

MeasuredBench parse_measured_bench(std::string_view text) {
  try {
    const auto j = nlohmann::json::parse(text);
    MeasuredBench b;
    const auto& measured = j.at("measured");
    b.date = measured.at("date").get<std::string>();
    b.provenance = measured.at("machine").get<std::string>();
    for (const auto& [what, commit] : measured.at("commits").items())
      b.provenance += "; " + what + ": " + commit.get<std::string>();
    for (const auto& q : j.at("questions")) {
      MeasuredQuestion m;
      m.id = q.at("id").get<std::string>();
      m.title = q.at("title").get<std::string>();
      m.categorical = q.at("kind").get<std::string>() == "label";
      const auto& ref = q.at("reference");
      m.reference_source = ref.at("source").get<std::string>();
      m.unit = ref.value("unit", "");
      m.reference = number(ref, "value");
      m.error_bar = number(ref, "error_bar");
      m.order = number(ref, "order");
      if (ref.contains("label")) m.reference_label = ref["label"].get<std::string>();
      for (const auto& a : q.at("answers")) m.answers.push_back(answer_of(a));
      b.questions.push_back(std::move(m));
    }
    return b;
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("bench table: ") + e.what());
  }
}

const MeasuredBench& measured_bench() {
  static const MeasuredBench table = parse_measured_bench(measured_bench_text());
  return table;
}

bool reference_resolves(const MeasuredQuestion& q, double tolerance) {
  if (q.categorical) return !q.reference_label.empty();
  return q.reference && (!q.error_bar || *q.error_bar <= tolerance * std::abs(*q.reference));
}

const MeasuredAnswer* cheapest_within(const MeasuredQuestion& q, double tolerance) {
  const MeasuredAnswer* best = nullptr;
  if (!reference_resolves(q, tolerance)) return best;
  for (const auto& a : q.answers) {
    if (a.status != "done" || !a.at_rest || !a.error || !a.wall_seconds || *a.error > tolerance)
      continue;
    if (!best || *a.wall_seconds < *best->wall_seconds) best = &a;
  }
  return best;
}

}  // namespace feedflow
