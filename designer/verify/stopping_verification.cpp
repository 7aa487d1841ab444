#include "designer/verify/stopping_verification.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <ostream>
#include <regex>
#include <tuple>

#include "designer/bench/bench_run.hpp"
#include "designer/verify/dem_run_estimate.hpp"
#include "designer/verify/rejudge.hpp"
#include "designer/verify/replace_beside.hpp"
#include "fullsim/common/progress_line.hpp"
#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

std::string mm(double metres) { return format_quantity(metres, "mm", 3); }

// Whether the layer flowed (true) or came to rest (false); none when the run gave no answer.
std::optional<bool> flows_in(const BenchRun& run) {
  if (!run.done() || !run.results.contains("layer_state") ||
      !run.results["layer_state"]["value"].is_string())
    return std::nullopt;
  return run.results["layer_state"]["value"].get<std::string>() != "at rest";
}

std::optional<double> measured_thickness(const BenchRun& run) {
  if (!run.done() || !run.results.contains("layer_thickness") ||
      !run.results["layer_thickness"]["value"].is_number())
    return std::nullopt;
  return run.results["layer_thickness"]["value"].get<double>();
}

// The layers kept below `runs_folder` for this question, whichever band or plan made them:
// thickness [m] -> flows. A folder counts when its name gives the thickness whose question
// names that folder again and its run reads back with an answer.
std::map<double, bool> kept_layers(const std::filesystem::path& runs_folder,
                                   const std::function<std::filesystem::path(double)>& folder_of,
                                   const std::function<std::optional<bool>(double)>& answer_of) {
  std::map<double, bool> kept;
  std::error_code ec;
  if (!std::filesystem::is_directory(runs_folder, ec)) return kept;
  static const std::regex thickness(R"(dem\.stopping_layer_([0-9]+(\.[0-9]+)?)mm)");
  for (const auto& entry : std::filesystem::directory_iterator(runs_folder, ec)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory(ec) || !std::regex_search(name, m, thickness)) continue;
    const double h = std::stod(m[1].str()) * 1e-3;
    if (folder_of(h) != entry.path()) continue;
    if (const auto flows = answer_of(h)) kept[h] = *flows;
  }
  return kept;
}

// The band the bisection starts from: the plan's, narrowed by kept layers to the thinnest that
// flowed and the thickest below it that came to rest.
std::pair<double, double> search_band(const StoppingVerificationPlan& plan,
                                      const std::map<double, bool>& kept) {
  std::optional<double> rests, flows;
  for (const auto& [h, f] : kept)
    if (f && !flows) flows = h;
  for (const auto& [h, f] : kept)
    if (!f && (!flows || h < *flows)) rests = h;
  double low = plan.low, high = plan.high;
  if (flows) {
    high = *flows;
    low = std::min(low, high - 2.0 * plan.tolerance);
  }
  if (rests) {
    low = *rests;
    if (!flows) high = std::max(high, low + 2.0 * plan.tolerance);
  }
  return {std::max(low, plan.floor), std::min(high, plan.ceiling)};
}

std::string outcomes(const ThresholdBisection& b) {
  std::string s;
  for (const auto& step : b.steps)
    s += (s.empty() ? "" : ", ") + mm(step.size) + (step.flows ? " flows" : " rests");
  return s;
}

}  // namespace

BenchQuestion layer_run_question(const std::string& case_file, const std::vector<std::string>& sets,
                                 double thickness) {
  return verification_run_question("verify_stopping", case_file, sets,
                                   "dem.stopping_layer=" + millimetres_setting(thickness));
}

BenchPoint layer_run_point() { return dem_verification_point("DEM layer", "layer_state"); }

StoppingVerificationPlan plan_stopping_verification(const Case& c, const DesignRecord& record,
                                                    double tolerance) {
  if (tolerance < 0.0)
    throw InputError("--thickness-tolerance", "",
                     "expected a positive thickness, e.g. 3 mm (or leave it out: one sphere)");
  if (!c.material.dem)
    throw InputError("--verify", "", "the material has no [dem] table for the particle rung");
  StoppingVerificationPlan plan;
  plan.law = c.dem.normal_law.empty() ? std::string("hysteretic_nonlinear2") : c.dem.normal_law;
  const double d = 2.0 * c.material.dem->particle.radius;
  plan.tolerance = tolerance > 0.0 ? tolerance : d;
  plan.floor = d;
  plan.ceiling = kLayerCeilingDiameters * d;
  if (plan.tolerance > 0.25 * (plan.ceiling - plan.floor))
    throw InputError("--thickness-tolerance", format_quantity(plan.tolerance, "mm", 3),
                     "at most a quarter of the layers' range (" + mm(plan.floor) + " .. " +
                         mm(plan.ceiling) + "), e.g. one sphere: " + mm(d));
  // The reduced band, kept within [one sphere, the ceiling] and at least two tolerances wide (a
  // band above the ceiling searches just below it); without one (no layer above theta2, or no
  // law), from one sphere to ten.
  double low = d, high = 10.0 * d;
  if (const Estimate* e = find_estimate(record.results, "stopping_thickness");
      e && e->is_number() && e->low && e->high && *e->high > 0.0) {
    const double per = e->unit == "mm" ? 1e-3 : 1.0;
    plan.reduced_low = *e->low * per;
    plan.reduced_high = *e->high * per;
    low = std::max(*plan.reduced_low, d);
    high = *plan.reduced_high;
  }
  low = std::min(low, plan.ceiling - 2.0 * plan.tolerance);
  high = std::clamp(high, low + 2.0 * plan.tolerance, plan.ceiling);
  low = std::min(low, high - 2.0 * plan.tolerance);
  plan.low = std::max(low, d);
  plan.high = high;
  plan.runs = bisection_runs(plan.low, plan.high, plan.tolerance);
  Case middle = c;
  middle.dem.stopping_layer = 0.5 * (plan.low + plan.high);
  const DemRunEstimate each = estimate_dem_layer_run(middle);
  plan.seconds = plan.runs * each.seconds;
  plan.cost = "about " + format_duration(plan.seconds) +
              " by its estimate: " + std::to_string(plan.runs) + " layers, each at " +
              mm(*middle.dem.stopping_layer) + " " + each.text() +
              " (a layer ends at rest, run away or flowing steadily, at most " +
              format_quantity(each.run_cap, "s", 3) + " after the tilt)";
  return plan;
}

StoppingVerification verify_stopping(const std::string& case_file,
                                     const std::vector<std::string>& sets,
                                     const StoppingVerificationPlan& plan, double budget,
                                     const std::filesystem::path& runs_folder,
                                     std::ostream* progress, const EarlierLayers& earlier) {
  StoppingVerification v;
  const BenchPoint point = layer_run_point();
  const auto folder_of = [&](double h) {
    return bench_run_folder(runs_folder, layer_run_question(case_file, sets, h), point);
  };
  // The layers kept cost nothing: the bisection replays those it would read back before its
  // first new one; when it needs a new one, those of any other search at the angle narrow its
  // band first (made from another band, say), and only the runs still to make are budgeted.
  const auto earlier_answer = [&](double h) { return answered_near(earlier, h, kLayerGrid); };
  const auto kept_answer = [&](double h) -> std::optional<bool> {
    if (const auto answer = earlier_answer(h)) return answer;
    const auto saved =
        saved_run_of(layer_run_question(case_file, sets, h), point, ".", folder_of(h));
    return saved ? flows_in(*saved) : std::nullopt;
  };
  double low = plan.low, high = plan.high;
  ThresholdBisection kept = bisect_flow_threshold(low, high, plan.tolerance, kept_answer,
                                                  plan.floor, plan.ceiling, kLayerGrid);
  if (kept.end == ThresholdBisection::End::stopped) {
    std::map<double, bool> layers = kept_layers(runs_folder, folder_of, kept_answer);
    layers.insert(earlier.begin(), earlier.end());
    std::tie(low, high) = search_band(plan, layers);
    if (low != plan.low || high != plan.high) {
      if (progress)
        *progress << "verify: layers kept from an earlier search narrow it to " << mm(low) << " .. "
                  << mm(high) << "\n";
      kept = bisect_flow_threshold(low, high, plan.tolerance, kept_answer, plan.floor, plan.ceiling,
                                   kLayerGrid);
    }
  }
  if (kept.end == ThresholdBisection::End::stopped) {
    const int runs = bisection_runs(low, high, plan.tolerance);
    const int to_make = std::max(1, runs - static_cast<int>(kept.steps.size()));
    const double needed = to_make * plan.seconds / plan.runs;
    if (needed > budget) {
      v.bisection = kept;
      v.seconds_needed = needed;
      for (const auto& step : kept.steps)  // the runs behind it, for the record's provenance
        if (!earlier_answer(step.size)) v.last_run = folder_of(step.size);
      v.status = "the bisection needs about " + std::to_string(to_make) + " more DEM layer" +
                 (to_make == 1 ? "" : "s") +
                 (kept.steps.empty() ? std::string()
                                     : " (" + std::to_string(kept.steps.size()) + " kept)") +
                 ", " + format_duration(needed) + " by their estimate, beyond the budget of " +
                 format_duration(budget) +
                 "; layers made are kept and read back, so a larger --budget continues";
      return v;
    }
  }
  double thickest_rest = 0.0;  // [m] trimmed thickness of the thickest layer at rest so far
  const auto judge_at = [&](double h) -> std::optional<bool> {
    if (progress) *progress << "verify: DEM layer " << mm(h) << " ..." << std::flush;
    if (const auto answer = earlier_answer(h)) {
      if (progress) *progress << ' ' << (*answer ? "flows" : "rests") << " (earlier record)\n";
      return answer;
    }
    bool made = false;
    v.last_run = folder_of(h);
    const BenchRun run =
        run_or_read_back(layer_run_question(case_file, sets, h), point, ".", v.last_run, made);
    if (made) v.wall_seconds += run.wall_seconds;
    const auto flows = flows_in(run);
    if (progress)
      *progress << ' ' << (flows ? (*flows ? "flows" : "rests") : run.status) << " ("
                << (made ? format_number(run.wall_seconds, 3) + " s" : std::string("read back"))
                << ")\n";
    if (!flows) v.status = run.done() ? "the DEM layer gave no answer" : run.status;
    if (flows && !*flows && h > thickest_rest) {
      thickest_rest = h;
      v.rested_thickness = measured_thickness(run);
    }
    return flows;
  };
  v.bisection = bisect_flow_threshold(low, high, plan.tolerance, judge_at, plan.floor, plan.ceiling,
                                      kLayerGrid);
  return v;
}

void apply_stopping_verification(const Case& c, const StoppingVerificationPlan& plan,
                                 const StoppingVerification& v, DesignRecord& record) {
  const std::string rung = "particle rung (DEM, " + plan.law + " law, periodic layers)";
  const std::string angle = format_quantity(std::get<Chute>(c.equipment).angle, "deg", 3);
  const std::string runs = format_number(v.wall_seconds, 3) + " s of runs";
  const ThresholdBisection& b = v.bisection;
  std::string note;
  using End = ThresholdBisection::End;
  if (b.end == End::stopped) {
    note = "stopping thickness not verified on the " + rung + ": " + v.status +
           (b.steps.empty() ? std::string() : " (layers so far: " + outcomes(b) + ")");
    if (b.stops_at < b.flows_at)  // both seen (NaN compares false): the bracket so far
      record.results.emplace_back(
          "stopping_thickness_so_far",
          particle_bracket(b.stops_at, b.flows_at,
                           "DEM (" + plan.law + ") periodic layers at " + angle +
                               ", cut short at " + mm(b.flows_at - b.stops_at) + " of " +
                               mm(plan.tolerance) + ": rests at " + mm(b.stops_at) + ", flows at " +
                               mm(b.flows_at)));
  } else if (b.end == End::bracketed) {
    const Estimate h =
        particle_bracket(b.stops_at, b.flows_at,
                         "DEM (" + plan.law + ") periodic layers at " + angle + ": rests at " +
                             mm(b.stops_at) + ", flows at " + mm(b.flows_at));
    replace_beside(record.results, "stopping_thickness", h);
    const bool inside =
        plan.reduced_low && b.stops_at <= *plan.reduced_high && b.flows_at >= *plan.reduced_low;
    note =
        std::string("stopping thickness ") + (inside ? "verified" : "contradicted") + " on the " +
        rung + ": a layer " + mm(b.stops_at) + " thick comes to rest" +
        (v.rested_thickness ? " (" + mm(*v.rested_thickness) + " measured at rest)"
                            : std::string()) +
        ", one " + mm(b.flows_at) + " thick flows on, " +
        (!plan.reduced_low ? std::string("where the reduced rung leaves no layer")
                           : (inside ? "meeting" : "outside") + std::string(" the reduced band ") +
                                 mm(*plan.reduced_low) + " .. " + mm(*plan.reduced_high)) +
        " (" + std::to_string(b.steps.size()) + " layers: " + outcomes(b) + "; " + runs +
        "); the verdict is judged on the DEM bracket";
  } else {
    const bool above = b.end == End::stops_at_high_edge;
    note = "stopping thickness contradicted on the " + rung + ": " +
           (above ? "a layer " + mm(plan.ceiling) + " thick (" +
                        format_number(kLayerCeilingDiameters, 3) +
                        " spheres) comes to rest, so h_stop is above it"
                  : "a layer of one sphere (" + mm(plan.floor) +
                        ") flows on, so h_stop is below what the layer can show") +
           " (" + outcomes(b) + "; " + runs + ")";
  }
  rejudge(c, record);
  record.verdict.reasons.push_back(std::move(note));
}

}  // namespace feedflow
