#include "designer/verify/rate_verification.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <ostream>

#include "designer/bench/bench_run.hpp"
#include "designer/bench/measured_bench.hpp"
#include "designer/calibrate/calibration_design.hpp"
#include "designer/verify/rejudge.hpp"
#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

constexpr double kBenchOutlet = 0.06;  // [m] the bench's pilot hopper question
constexpr double kSimulatedTime = 1.0; // [s] after the opening, as the bench measured

// The bench's CEL levels of the pilot hopper: cells across the half outlet -> (value, wall time).
struct MeasuredLevel {
  double value = 0.0, seconds = 0.0;
};

std::map<double, MeasuredLevel> measured_levels(const MeasuredQuestion& q) {
  std::map<double, MeasuredLevel> levels;
  for (const auto& a : q.answers) {
    if (a.rung != "L2" || !a.in_reference || a.status != "done" || !a.value || !a.wall_seconds) continue;
    const double across = std::strtod(a.resolution.c_str(), nullptr);
    if (across > 0.0) levels[std::round(across)] = {*a.value, *a.wall_seconds};
  }
  return levels;
}

// The CEL flow pattern in place of the reduced one (kept beside it); what the verdict says of it.
// On a cone the CEL's pattern stands beside the reduced one instead (flow_pattern_continuum):
// the axisymmetric grid's wall zone slows under refinement, so its reading is not a verification.
std::string verify_flow_pattern(const RateVerification& v, bool cone, Estimates& results) {
  const auto it = std::find_if(results.begin(), results.end(), [](const auto& r) { return r.first == "flow_pattern"; });
  if (v.flow_pattern.empty() || it == results.end() || !std::holds_alternative<std::string>(it->second.value)) return {};
  const Estimate reduced = it->second;
  const std::string before = std::get<std::string>(reduced.value);
  Estimate cel;
  cel.value = v.flow_pattern;
  cel.model = v.flow_pattern_model;
  cel.rung = Rung::L2;
  if (cone) {
    results.emplace(it + 1, "flow_pattern_continuum", cel);
    return "flow pattern not verified on the continuum rung: CEL " + v.flow_pattern + ", reduced " + before +
           " (kept). On the axisymmetric grid the cone's wall zone slows as the cells shrink, mass flow on coarse "
           "cells turning to funnel flow on fine ones (the CEL run's assumptions give the measured ratios), "
           "so the CEL's pattern on a cone is shown, not used";
  }
  it->second = cel;
  results.emplace(it + 1, reduced_model_key("flow_pattern"), reduced);
  return std::string(before == v.flow_pattern ? "flow pattern verified" : "flow pattern contradicted") +
         " on the continuum rung: reduced " + before + ", CEL " + v.flow_pattern + " (" + v.flow_pattern_model + ")";
}

}  // namespace

RateVerificationPlan plan_rate_verification(const Hopper& h, double tolerance, double budget) {
  RateVerificationPlan plan;
  const MeasuredBench& table = measured_bench();
  const MeasuredQuestion* q = table.find("hopper_discharge_rate_60mm");
  const auto levels = q ? measured_levels(*q) : std::map<double, MeasuredLevel>{};
  if (!q || !q->reference || !levels.count(3) || !levels.count(6) || !levels.count(12)) {
    plan.description = "the shipped bench table has no CEL series of the pilot hopper's rate to plan with";
    return plan;
  }
  const double scale = std::pow(kBenchOutlet / h.outlet_width, 3.0);  // t ~ W^-3 at fixed cells across
  const double order = measured_hopper_rate_order().order;
  struct Option {
    std::vector<double> cells;
    double error;
  };
  const double f3 = levels.at(3).value, f6 = levels.at(6).value;
  const double two_level_value = f6 + (f6 - f3) / (std::pow(2.0, order) - 1.0);
  const Option options[] = {
      {{3, 6}, 3.0 * std::abs(f6 - f3) / (std::pow(2.0, order) - 1.0) / std::abs(two_level_value)},
      {{3, 6, 12}, q->error_bar.value_or(0.0) / std::abs(*q->reference)},
  };
  std::string considered;
  for (const auto& o : options) {
    double seconds = 0.0;
    for (double n : o.cells) seconds += levels.at(n).seconds * scale;
    std::string cells;
    for (double n : o.cells) cells += (cells.empty() ? "" : ", ") + format_number(n, 3);
    const std::string text = "CEL at " + cells + " cells across the half outlet (error bar " +
                             format_number(100 * o.error, 3) + " % on the pilot hopper, about " +
                             format_quantity(seconds, "min", 2) + ")";
    if (o.error <= tolerance && seconds <= budget) {
      plan.cells_across = o.cells;
      plan.expected_error = o.error;
      plan.estimated_seconds = seconds;
      // A cone runs axisymmetric on the grid of the wedge's half slice: the same cells, steps and
      // cost; its error is taken to be the wedge's (the bench measures the wedge only).
      plan.description = text + (h.is_wedge() ? "" : "; the cone runs axisymmetric on a grid of the wedge's size, "
                                                    "its error taken as the pilot wedge's");
      return plan;
    }
    considered += (considered.empty() ? "" : "; ") + text;
  }
  plan.description = "no plan meets " + format_number(100 * tolerance, 3) + " % within " +
                     format_quantity(budget, "min", 3) + ": " + considered;
  return plan;
}

RateVerification verify_rate(const std::string& case_file, const std::vector<std::string>& sets, const Hopper& h,
                             const RateVerificationPlan& plan, const std::filesystem::path& runs_folder,
                             std::ostream* progress) {
  CalibrationDesign design;
  design.case_file = case_file;
  design.points = {{h.outlet_width, h.semi_angle, false}};
  design.cells_across = plan.cells_across;
  design.time = kSimulatedTime;
  BenchQuestion q = design_point_question(design, design.points.front());
  q.sets.insert(q.sets.begin(), sets.begin(), sets.end());  // the user's overrides first, the point's win
  RateVerification v;
  std::map<std::string, BenchRun> runs;
  for (const auto& p : q.points) {
    if (progress) *progress << "verify: " << bench_invocation(q, p) << " ..." << std::flush;
    bool made = false;
    BenchRun run = run_or_read_back(q, p, ".", bench_run_folder(runs_folder, q, p), made);
    v.wall_seconds += made ? run.wall_seconds : 0.0;
    if (progress) *progress << (made ? " " + format_number(run.wall_seconds, 3) + " s" : std::string(" read back")) << '\n';
    if (!run.done()) v.status = run.status;
    runs[point_id(p)] = std::move(run);
    if (v.status != "done") return v;
  }
  v.finest_run = bench_run_folder(runs_folder, q, q.points.back());
  v.reference = tabulate(q, runs).reference;
  if (!v.reference.value) v.status = "the CEL runs gave no rate";
  const auto& finest = runs.at(point_id(q.points.back())).results;
  if (finest.contains("flow_pattern") && finest["flow_pattern"]["value"].is_string()) {
    v.flow_pattern = finest["flow_pattern"]["value"].get<std::string>();
    v.flow_pattern_model = finest["flow_pattern"].value("model", "");
  }
  return v;
}

void apply_rate_verification(const Case& c, const RateVerification& v, DesignRecord& record) {
  const auto it = std::find_if(record.results.begin(), record.results.end(),
                               [](const auto& r) { return r.first == "mass_flow_rate"; });
  if (it == record.results.end()) return;
  if (v.status != "done") {
    record.verdict.reasons.push_back("mass flow rate not verified: " + v.status);
    return;
  }
  const Estimate reduced = it->second;
  Estimate verified;
  verified.value = *v.reference.value;
  verified.unit = "kg/s";
  verified.low = *v.reference.value - v.reference.error_bar.value_or(0.0);
  verified.high = *v.reference.value + v.reference.error_bar.value_or(0.0);
  verified.model = v.reference.source;
  verified.rung = Rung::L2;
  verified.display_unit = reduced.display_unit;
  it->second = verified;
  record.results.emplace(it + 1, reduced_model_key("mass_flow_rate"), reduced);
  const auto* hopper = std::get_if<Hopper>(&c.equipment);
  const std::string pattern_note = verify_flow_pattern(v, hopper && !hopper->is_wedge(), record.results);
  const double value = std::get<double>(reduced.value);
  // Verified when the reduced band and the CEL interval overlap: the two agree within what each knows.
  const double lo = *v.reference.value - v.reference.error_bar.value_or(0.0);
  const double hi = *v.reference.value + v.reference.error_bar.value_or(0.0);
  const bool holds = reduced.low.value_or(value) <= hi && lo <= reduced.high.value_or(value);
  const std::string numbers = "reduced " + format_number(value, 4) + " kg/s (band " +
                              format_number(reduced.low.value_or(value), 4) + " .. " +
                              format_number(reduced.high.value_or(value), 4) + "), CEL " +
                              format_number(*v.reference.value, 4) + " +- " +
                              format_number(v.reference.error_bar.value_or(0.0), 3) + " kg/s";
  rejudge(c, record);  // on the CEL rate
  record.verdict.reasons.push_back(std::string(holds ? "mass flow rate verified" : "mass flow rate contradicted") +
                                   " on the continuum rung: " + numbers + " (" + v.reference.source + ", " +
                                   format_number(v.wall_seconds, 3) + " s of runs); the verdict is judged on the CEL rate");
  if (!pattern_note.empty()) record.verdict.reasons.push_back(pattern_note);
}

}  // namespace feedflow
