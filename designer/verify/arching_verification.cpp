#include "designer/verify/arching_verification.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <tuple>

#include "designer/bench/bench_run.hpp"
#include "designer/verify/dem_run_estimate.hpp"
#include "designer/verify/rejudge.hpp"
#include "designer/verify/replace_beside.hpp"
#include "fullsim/common/progress_line.hpp"
#include "models/contact/contact_law_registry.hpp"
#include "models/core/errors.hpp"
#include "models/hopper/critical_outlet.hpp"
#include "models/units/quantity_format.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

// Whether the case's DEM contacts can pull (a cohesion part that lets the law's K_nc branch act).
bool contacts_pull(const Case& c) {
  return with_contact_law(
      choose_contact_law(c.dem.normal_law, {}, {}, c.dem.cohesion),
      [](auto law) { return decltype(law)::type::CohesionPart::kNeedsCohesionBranch; });
}

std::string mm(double metres) { return format_quantity(metres, "mm", 4); }

// [m] two widths this close are one (a record keeps a width to a nanometre).
constexpr double kWidthMatch = 1e-6;

std::optional<OutletOutcome> outcome_of(const BenchRun& run) {
  if (!run.done() || !run.results.contains("arching") ||
      !run.results["arching"]["value"].is_string())
    return std::nullopt;
  return run.results["arching"]["value"].get<std::string>() == "arched" ? OutletOutcome::arches
                                                                        : OutletOutcome::flows;
}

// The run's flow pattern, when it flowed and measured one (an arched run has no steady window).
std::optional<ParticleFlowPattern> flow_pattern_of(const BenchRun& run, const std::string& law,
                                                   double outlet) {
  const auto& r = run.results;
  if (!run.done() || !r.contains("flow_pattern") || !r["flow_pattern"]["value"].is_string())
    return std::nullopt;
  const auto number = [&](const char* key) -> std::optional<double> {
    if (!r.contains(key) || !r[key]["value"].is_number()) return std::nullopt;
    return r[key]["value"].get<double>();
  };
  std::string read;
  if (const auto ratio = number("wall_to_centre_speed_ratio"))
    read += "wall/centre speed " + format_number(*ratio, 3);
  if (const auto fifo = number("fifo_index"))
    read += (read.empty() ? "" : ", ") + std::string("FIFO index ") + format_number(*fifo, 3);
  if (const auto dead = number("stagnant_zone_width"); dead && *dead > 0.0)
    read += ", stagnant zone " + format_quantity(*dead * 1e-3, "mm", 3);
  const std::string where = "DEM (" + law + ") at the design outlet " + mm(outlet);
  return ParticleFlowPattern{r["flow_pattern"]["value"].get<std::string>(),
                             read.empty() ? where : where + ": " + read, read};
}

std::string outcomes(const WidthBisection& b) {
  std::string s;
  for (const auto& step : b.steps)
    s += (s.empty() ? "" : ", ") + mm(step.width) + " " + to_string(step.outcome);
  return s;
}

// Where the rung's width goes in the record: in place of the reduced one, unless the DEM's
// spheres are not the material's grains (coarse-grained): then beside it, as the spheres' own.
std::string result_key(const Case& c, const ArchingVerificationPlan& plan) {
  if (plan.quantity != "mechanical_arching_width") return plan.quantity;
  const double d90 = c.material.psd ? c.material.psd->d90 : 0.0;
  return std::abs(plan.sphere_diameter - d90) <= 0.1 * d90 ? plan.quantity
                                                           : "mechanical_arching_width_dem_spheres";
}

}  // namespace

BenchQuestion arching_run_question(const std::string& case_file,
                                   const std::vector<std::string>& sets, double w) {
  return verification_run_question("verify_arching", case_file, sets,
                                   "hopper.outlet_width=" + millimetres_setting(w));
}

BenchPoint arching_run_point() { return dem_verification_point("DEM", "arching"); }

std::optional<Case> with_cohesive_contacts(const Case& c) {
  if (!c.dem.cohesion.empty()) return std::nullopt;
  const bool has_branch = with_contact_law(choose_contact_law(c.dem.normal_law), [](auto law) {
    return decltype(law)::type::NormalPart::kHasCohesionBranch;
  });
  if (!has_branch) return std::nullopt;
  Case cohesive = c;
  cohesive.dem.cohesion = "k_nc";
  return cohesive;
}

ArchingVerificationPlan plan_arching_verification(const Case& c, const DesignRecord& record,
                                                  double tolerance) {
  if (!(tolerance > 0.0))
    throw InputError("--width-tolerance", "", "expected a positive width, e.g. 1 mm");
  ArchingVerificationPlan plan;
  plan.law = c.dem.normal_law.empty() ? std::string("hysteretic_nonlinear2") : c.dem.normal_law;
  plan.tolerance = tolerance;
  if (contacts_pull(c)) {
    plan.law += " + k_nc cohesion";
    plan.quantity = "critical_outlet_width";
    const Estimate* band = find_estimate(record.results, plan.quantity);
    if (!band || !band->is_number() || !band->low || !band->high || !(*band->high > *band->low))
      throw InputError("--verify", "",
                       "the design check gave no band of the critical outlet width to search");
    const double per = band->unit == "mm" ? 1e-3 : 1.0;
    plan.low = *band->low * per;
    plan.high = *band->high * per;
  } else {
    // Interlocking arches form at (3-8) d of the grains that interlock: the DEM's spheres, which
    // may be coarse-grained, not the material's d90.
    if (!c.material.dem)
      throw InputError("--verify", "", "the material has no [dem] table for the particle rung");
    const auto rule = mechanical_arching_width(2.0 * c.material.dem->particle.radius);
    plan.quantity = "mechanical_arching_width";
    plan.sphere_diameter = 2.0 * c.material.dem->particle.radius;
    plan.low = rule.low;
    plan.high = rule.high;
  }
  plan.runs = 1 + bisection_runs(plan.low, plan.high, tolerance);
  return plan;
}

ArchingVerificationCost estimate_arching_verification(const Case& c, const DesignRecord& record,
                                                      const ArchingVerificationPlan& plan) {
  const Estimate* rate = find_estimate(record.results, "mass_flow_rate");
  const double q =
      rate && rate->is_number() && rate->unit == "kg/s" ? std::get<double>(rate->value) : 0.0;
  const double w = std::get<Hopper>(c.equipment).outlet_width,
               middle = 0.5 * (plan.low + plan.high);
  const DemRunEstimate at_outlet = estimate_dem_hopper_run(c, q);
  Case narrower = c;
  std::get<Hopper>(narrower.equipment).outlet_width = middle;
  const DemRunEstimate in_band = estimate_dem_hopper_run(narrower, q * std::pow(middle / w, 1.5));
  ArchingVerificationCost cost;
  cost.seconds = at_outlet.seconds + (plan.runs - 1) * in_band.seconds;
  cost.outlet_seconds = at_outlet.seconds;
  const double longest = at_outlet.longest_seconds + (plan.runs - 1) * in_band.longest_seconds;
  cost.text = "about " + format_duration(cost.seconds) +
              " by its estimate, each run emptying at the reduced rate, at most " +
              format_duration(longest) + " should each flow on until " +
              format_quantity(at_outlet.run_cap, "s", 3) +
              " after the opening (one that arches stops sooner): the outlet's run " +
              at_outlet.text() + "; each of the " + std::to_string(plan.runs - 1) + " more at " +
              mm(middle) + " " + in_band.text();
  return cost;
}

ArchingVerification verify_arching(const std::string& case_file,
                                   const std::vector<std::string>& sets, const Hopper& h,
                                   const ArchingVerificationPlan& plan, double budget,
                                   const std::filesystem::path& runs_folder, std::ostream* progress,
                                   const EarlierArching& earlier) {
  ArchingVerification v;
  const auto earlier_outcome = [&](double w) {
    return answered_near(earlier.widths, w, kWidthMatch);
  };
  const auto judge_at = [&](double w) -> std::optional<OutletOutcome> {
    if (progress) *progress << "verify: DEM at outlet " << mm(w) << " ..." << std::flush;
    if (const auto outcome = earlier_outcome(w)) {
      if (progress) *progress << ' ' << to_string(*outcome) << " (earlier record)\n";
      return outcome;
    }
    bool made = false;
    const BenchQuestion q = arching_run_question(case_file, sets, w);
    const BenchRun run = run_or_read_back(
        q, arching_run_point(), ".", bench_run_folder(runs_folder, q, arching_run_point()), made);
    if (made) v.wall_seconds += run.wall_seconds;
    v.longest_run = std::max(v.longest_run, run.wall_seconds);  // a run read back keeps its time
    const auto outcome = outcome_of(run);
    if (progress)
      *progress << ' ' << (outcome ? to_string(*outcome) : run.status) << " ("
                << (made ? format_number(run.wall_seconds, 3) + " s" : std::string("read back"))
                << ")\n";
    if (!outcome) v.status = run.done() ? "the DEM run gave no arching answer" : run.status;
    return outcome;
  };
  v.design_run = bench_run_folder(
      runs_folder, arching_run_question(case_file, sets, h.outlet_width), arching_run_point());
  const bool design_kept = saved_run_of(arching_run_question(case_file, sets, h.outlet_width),
                                        arching_run_point(), ".", v.design_run)
                               .has_value();
  if (earlier.at_design && !design_kept) {
    if (progress)
      *progress << "verify: DEM at outlet " << mm(h.outlet_width) << " ... "
                << to_string(*earlier.at_design) << " (earlier record)\n";
    v.at_design = earlier.at_design;
    v.flow_pattern = earlier.flow_pattern;
    v.design_run.clear();
  } else {
    if (!design_kept && plan.outlet_seconds > budget) {
      v.status = "its run at the design outlet takes about " +
                 format_duration(plan.outlet_seconds) + " by its estimate, beyond the budget of " +
                 format_duration(budget);
      return v;
    }
    v.at_design = judge_at(h.outlet_width);
    if (const auto run = saved_run_of(arching_run_question(case_file, sets, h.outlet_width),
                                      arching_run_point(), ".", v.design_run))
      v.flow_pattern = flow_pattern_of(*run, plan.law, h.outlet_width);
  }
  if (!v.at_design) return v;
  // An earlier record's bracket is where the bisection starts: its widest outlet that arched
  // below its narrowest that flowed.
  double low = plan.low, high = plan.high;
  std::optional<double> arched, flowed;
  for (const auto& [w, outcome] : earlier.widths)
    if (outcome == OutletOutcome::flows && !flowed) flowed = w;
  for (const auto& [w, outcome] : earlier.widths)
    if (outcome == OutletOutcome::arches && (!flowed || w < *flowed)) arched = w;
  if (arched && flowed) std::tie(low, high) = std::pair{*arched, *flowed};
  // The bisection's runs already kept cost nothing: those it would read back before its first
  // new one.
  const auto kept_outcome = [&](double w) -> std::optional<OutletOutcome> {
    if (const auto outcome = earlier_outcome(w)) return outcome;
    const BenchQuestion q = arching_run_question(case_file, sets, w);
    const auto saved = saved_run_of(q, arching_run_point(), ".",
                                    bench_run_folder(runs_folder, q, arching_run_point()));
    return saved ? outcome_of(*saved) : std::nullopt;
  };
  const WidthBisection kept = bisect_outlet_width(low, high, plan.tolerance, kept_outcome);
  const int to_make = kept.end == WidthBisection::End::stopped
                          ? std::max(0, bisection_runs(low, high, plan.tolerance) -
                                            static_cast<int>(kept.steps.size()))
                          : 0;
  // Each as long as the slowest run seen, or (none made here) the design outlet's estimate.
  const double each = v.longest_run > 0.0 ? v.longest_run : plan.outlet_seconds;
  const double needed = to_make * each;
  if (needed > budget) {
    v.bisection = kept;
    v.seconds_needed = needed;
    v.status =
        "the bisection needs " + std::to_string(to_make) + " more DEM run" +
        (to_make == 1 ? "" : "s") +
        (kept.steps.empty() ? std::string()
                            : " (" + std::to_string(kept.steps.size()) + " of its runs kept)") +
        " of about " + format_duration(each) + " each (" + format_duration(needed) +
        "), beyond the budget of " + format_duration(budget) +
        "; runs made are kept and read back, so a larger --budget continues";
    return v;
  }
  v.bisection = bisect_outlet_width(low, high, plan.tolerance, judge_at);
  return v;
}

void apply_arching_verification(const Case& c, const ArchingVerificationPlan& plan,
                                const ArchingVerification& v, DesignRecord& record) {
  const std::string rung = "particle rung (DEM, " + plan.law + " law)";
  const std::string runs = format_number(v.wall_seconds, 3) + " s of runs";
  std::vector<std::string> notes;
  if (v.at_design) {
    Estimate observed;
    observed.value =
        *v.at_design == OutletOutcome::arches ? std::string("arched") : std::string("flowing");
    observed.model = "DEM (" + plan.law + ") at the design outlet " +
                     mm(std::get<Hopper>(c.equipment).outlet_width);
    observed.rung = Rung::L3;
    replace_beside(record.results, "arching", observed);
  }
  const auto reduced_pattern =
      std::find_if(record.results.begin(), record.results.end(),
                   [](const auto& r) { return r.first == "flow_pattern"; });
  if (v.flow_pattern && reduced_pattern != record.results.end() &&
      std::holds_alternative<std::string>(reduced_pattern->second.value)) {
    const std::string before = std::get<std::string>(reduced_pattern->second.value);
    Estimate observed;
    observed.value = v.flow_pattern->pattern;
    observed.model = v.flow_pattern->model;
    observed.rung = Rung::L3;
    replace_beside(record.results, "flow_pattern", observed);
    notes.push_back(
        std::string(before == v.flow_pattern->pattern ? "flow pattern verified"
                                                      : "flow pattern contradicted") +
        " on the " + rung + ": reduced " + before + ", DEM " + v.flow_pattern->pattern +
        " at the design outlet" +
        (v.flow_pattern->read.empty() ? std::string() : " (" + v.flow_pattern->read + ")"));
  }
  const WidthBisection& b = v.bisection;
  const std::string what = quantity_label(plan.quantity);
  const std::string band =
      (plan.quantity == "critical_outlet_width" ? "the reduced band "
                                                : "the rule's range 3 d .. 8 d = ") +
      mm(plan.low) + " .. " + mm(plan.high);
  if (!v.at_design || b.end == WidthBisection::End::stopped) {
    notes.push_back(what + " not verified on the " + rung + ": " + v.status +
                    (b.steps.empty() ? std::string() : " (runs so far: " + outcomes(b) + ")"));
    if (b.arches_at < b.flows_at)  // both seen (NaN compares false): the bracket so far
      record.results.emplace_back(
          result_key(c, plan) + "_so_far",
          particle_bracket(b.arches_at, b.flows_at,
                           "DEM (" + plan.law + ") bisection, cut short at " +
                               mm(b.flows_at - b.arches_at) + " of " + mm(plan.tolerance) +
                               ": arches at " + mm(b.arches_at) + ", flows at " + mm(b.flows_at)));
  } else if (b.end == WidthBisection::End::bracketed) {
    const Estimate width = particle_bracket(b.arches_at, b.flows_at,
                                            "DEM (" + plan.law + ") bisection: arches at " +
                                                mm(b.arches_at) + ", flows at " + mm(b.flows_at));
    replace_beside(record.results, result_key(c, plan), width);
    notes.push_back(what + " verified on the " + rung + ": it arches at " + mm(b.arches_at) +
                    " and flows at " + mm(b.flows_at) + ", inside " + band + " (" +
                    std::to_string(b.steps.size()) + " widths: " + outcomes(b) + "; " + runs +
                    "); the verdict is judged on the DEM bracket");
  } else {
    const bool above = b.end == WidthBisection::End::arches_at_high_edge;
    notes.push_back(what + " contradicted on the " + rung + ": it " +
                    (above ? "arches at " + mm(plan.high) + ", so the width is above "
                           : "flows at " + mm(plan.low) + ", so the width is below ") +
                    band + " (" + runs + ")");
  }
  if (plan.quantity == "mechanical_arching_width")
    notes.push_back(
        "the DEM contacts (" + plan.law +
        ", cohesion none) do not pull: their arches are interlocking ones, so it verifies the "
        "interlocking rule (3-8) d on its " +
        mm(plan.sphere_diameter) +
        " spheres, searched between 3 d and 8 d, not the cohesive B_c (the seed's hysteretic law "
        "with dem.cohesion = k_nc can)" +
        (result_key(c, plan) == plan.quantity
             ? std::string()
             : "; the spheres are not the material's grains (d90 " +
                   (c.material.psd ? mm(c.material.psd->d90) : std::string("not given")) +
                   "), so the material's own interlocking width stays the reduced one"));
  rejudge(c, record);
  for (auto& n : notes) record.verdict.reasons.push_back(std::move(n));
}

}  // namespace feedflow
