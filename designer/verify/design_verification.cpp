#include "designer/verify/design_verification.hpp"

#include <cmath>

#include "designer/bench/bench_plan.hpp"
#include "designer/calibrate/stopping_records.hpp"
#include "designer/calibrate/verified_record.hpp"
#include "designer/simulate/solver_choice.hpp"
#include "designer/verify/arching_verification.hpp"
#include "designer/verify/cel_chute_estimate.hpp"
#include "designer/verify/dem_run_estimate.hpp"
#include "designer/verify/rate_verification.hpp"
#include "designer/verify/simulation_verification.hpp"
#include "designer/verify/stopping_verification.hpp"
#include "fullsim/common/progress_line.hpp"
#include "models/core/errors.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

double parsed(const std::string& text, const Dimension& d, const char* flag, const char* example) {
  try {
    const double v = parse_quantity_as(text, d, d == dim::dimensionless);
    if (v > 0.0) return v;
  } catch (const std::invalid_argument&) {
  }
  throw InputError(flag, text,
                   std::string("expected a positive ") + dimension_name(d) + ", e.g. " + example);
}

// Whether a finding of the verdict on `quantity` was marginal.
bool marginal_on(const DesignRecord& r, const std::string& quantity) {
  for (const auto& f : r.verdict.findings)
    if (f.quantity == quantity && f.status == VerdictStatus::marginal) return true;
  return false;
}

std::string shell_word(const std::string& a) {
  return a.find(' ') == std::string::npos ? a : "\"" + a + "\"";
}

// "feedflow design CASE --set ...": this check as typed, to name the command that settles it.
std::string this_check(const VerificationRequest& args) {
  std::string again = "feedflow design " + shell_word(args.case_file);
  for (const auto& set : args.sets) again += " --set " + shell_word(set);
  if (!args.start_from.empty()) again += " --start-from " + shell_word(args.start_from.string());
  return again;
}

// A --budget that holds `seconds` of estimated runs with a fifth to spare: "13h", "40min".
std::string budget_holding(double seconds) {
  const double spared = 1.2 * seconds;
  return spared > 7200.0 ? format_number(std::ceil(spared / 3600.0), 3) + "h"
                         : format_number(std::ceil(spared / 60.0), 3) + "min";
}

// What an earlier record of the hopper's --verify dem answered (--start-from): its bracket's two
// widths (finished or cut short) and, of the same outlet, the design outlet's run; nothing without
// one. InputError (naming the file and the key) when it is no such record, or of another hopper
// (but its outlet), material or law.
EarlierArching earlier_arching(const std::filesystem::path& file, const Case& c,
                               const DesignRecord& record, const ArchingVerificationPlan& plan) {
  if (file.empty()) return {};
  const VerifiedRecord j = VerifiedRecord::read(file, "--start-from", "hopper", c.material.name);
  if (c.material.dem) check_sphere_radius(file, j.sphere_radius(), c.material.dem->particle.radius);
  const Hopper& h = std::get<Hopper>(c.equipment);
  const std::string where = file.string();
  if (const std::string shape = j.text({"inputs", "hopper", "shape"}, "wedge or conical");
      shape != h.shape)
    throw InputError(where, "inputs.hopper.shape",
                     "expected the case's " + h.shape + ", got " + shape);
  // Every hopper input the record resolved but the outlet, as this check resolved it.
  for (const InputValue& in : record.inputs) {
    const double* value = std::get_if<double>(&in.value);
    if (!value || in.key.rfind("hopper.", 0) != 0 || in.key == "hopper.outlet_width") continue;
    const std::string name = in.key.substr(7);
    const double was = j.number({"inputs", "hopper", name}, in.display + " as here");
    if (std::abs(was - *value) > 1e-9 * std::max(1.0, std::abs(*value)))
      throw InputError(where, "inputs." + in.key,
                       "expected the case's " + in.display + " (" + format_number(*value, 6) + " " +
                           in.si_unit + "), got " + format_number(was, 6) + " " + in.si_unit);
  }
  EarlierArching earlier;
  const auto& results = j.json["results"];
  const auto on_particles = [&](const std::string& key) {
    return results.contains(key) && results[key].is_object() &&
           results[key].value("rung", "") == "L3";
  };
  // "DEM (hysteretic_nonlinear2 + k_nc cohesion) ..." -> the law, which must be the plan's.
  const auto check_law = [&](const std::string& key) {
    if (const std::string law = j.dem_law(key); law != plan.law)
      throw InputError(where, "results." + key + ".model",
                       "expected runs of the " + plan.law + " law, got " + law);
  };
  for (const std::string& key : {plan.quantity, plan.quantity + "_dem_spheres"})
    for (const std::string& entry : {key, key + "_so_far"})
      if (earlier.widths.empty() && on_particles(entry)) {
        check_law(entry);
        const double arches =
            j.number({"results", entry, "low"}, "the widest outlet that arched [m]");
        const double flows =
            j.number({"results", entry, "high"}, "the narrowest outlet that flowed [m]");
        if (!(arches > 0.0 && arches < flows))
          throw InputError(where, "results." + entry,
                           "expected a bracket: an outlet that arched below one that flowed");
        earlier.widths = {{arches, OutletOutcome::arches}, {flows, OutletOutcome::flows}};
      }
  if (on_particles("arching") &&
      std::abs(j.number({"inputs", "hopper", "outlet_width"}, "the outlet width [m]") -
               h.outlet_width) < 1e-9) {
    check_law("arching");
    earlier.at_design = j.text({"results", "arching", "value"}, "arched or flowing") == "arched"
                            ? OutletOutcome::arches
                            : OutletOutcome::flows;
    if (on_particles("flow_pattern"))
      earlier.flow_pattern = ParticleFlowPattern{
          j.text({"results", "flow_pattern", "value"}, "mass or funnel"),
          j.text({"results", "flow_pattern", "model"}, "what the pattern was read from"), ""};
  }
  if (earlier.widths.empty() && !earlier.at_design)
    throw InputError(where, "results." + plan.quantity,
                     "expected a record of `design --verify dem` on the particle rung: its "
                     "bracket, or its run at this outlet");
  return earlier;
}

// --verify dem on a hopper: arching at the design outlet and the arching width by bisection on
// the particle rung. Returns false when Ctrl-C stopped the runs.
bool dem_verification(const VerificationRequest& args, const Case& c, const Hopper& h,
                      const std::filesystem::path& runs, DesignRecord& record) {
  const double width_tolerance =
      parsed(args.width_tolerance, dim::length, "--width-tolerance", "1 mm");
  const double budget = parsed(args.budget, dim::time, "--budget", "10 min");
  ArchingVerificationPlan plan = plan_arching_verification(c, record, width_tolerance);
  std::optional<ArchingVerificationCost> cost;
  try {
    cost = estimate_arching_verification(c, record, plan);
    plan.outlet_seconds = cost->outlet_seconds;
  } catch (const InputError&) {  // the scene says why when the run is made
  }
  if (args.log)
    *args.log << "verify: " << quantity_label(plan.quantity) << " on the particle rung ("
              << plan.law << "): the design outlet " << format_quantity(h.outlet_width, "mm", 4)
              << ", then outlets from " << format_quantity(plan.low, "mm", 4) << " to "
              << format_quantity(plan.high, "mm", 4) << " to "
              << format_quantity(plan.tolerance, "mm", 3) << " (" << plan.runs << " runs)"
              << (cost ? ": " + cost->text : std::string()) << '\n';
  const EarlierArching earlier = earlier_arching(args.start_from, c, record, plan);
  install_interrupt_handler();
  ArchingVerification v =
      verify_arching(args.case_file, args.sets, h, plan, budget, runs, args.log, earlier);
  if (v.status == "interrupted") return false;
  std::string again = this_check(args) + " --verify dem";
  if (args.width_tolerance != VerificationRequest{}.width_tolerance)
    again += " --width-tolerance " + shell_word(args.width_tolerance);
  if (!v.at_design && cost)  // refused on the budget: the command that holds it
    v.status += ": " + again + " --budget " + budget_holding(cost->outlet_seconds) +
                " makes the design outlet's run, --budget " + budget_holding(cost->seconds) +
                " the whole plan";
  else if (v.seconds_needed > 0.0)
    v.status += ": " + again + " --budget " + budget_holding(v.seconds_needed);
  apply_arching_verification(c, plan, v, record);
  if (v.at_design && !v.design_run.empty())
    record.simulation_runs.push_back(std::filesystem::absolute(v.design_run).string());
  return true;
}

// The bracket of an earlier record of the chute's --verify dem (--start-from), its layer at rest
// and its layer flowing; none without one. InputError (naming the file and the key) when it is no
// such record or another angle's, material's or law's.
EarlierLayers earlier_layers(const std::filesystem::path& file, const Case& c,
                             const StoppingVerificationPlan& plan) {
  if (file.empty()) return {};
  const StoppingRecord r = read_stopping_record(file, c.material.name, "--start-from");
  const double angle = std::get<Chute>(c.equipment).angle;
  if (std::abs(r.observation.angle - angle) > 1e-9)
    throw InputError(file.string(), "inputs.chute.angle",
                     "expected the chute's angle " + format_quantity(angle, "deg", 4) + ", got " +
                         format_quantity(r.observation.angle, "deg", 4));
  if (r.law != plan.law)
    throw InputError(file.string(), "results.stopping_thickness.model",
                     "expected layers of the " + plan.law + " law, got " + r.law);
  check_sphere_radius(file, r.sphere_radius, c.material.dem->particle.radius);
  return {{r.stops_at, false}, {r.flows_at, true}};
}

// --verify dem on a chute: h_stop at its angle bracketed by a bisection of DEM stopping layers.
// Returns false when Ctrl-C stopped the runs.
bool stopping_verification(const VerificationRequest& args, const Case& c,
                           const std::filesystem::path& runs, DesignRecord& record) {
  const double tolerance =
      args.thickness_tolerance.empty()
          ? 0.0
          : parsed(args.thickness_tolerance, dim::length, "--thickness-tolerance", "3 mm");
  const double budget = parsed(args.budget, dim::time, "--budget", "10 min");
  const StoppingVerificationPlan plan = plan_stopping_verification(c, record, tolerance);
  if (args.log)
    *args.log << "verify: h_stop at "
              << format_quantity(std::get<Chute>(c.equipment).angle, "deg", 3)
              << " on the particle rung, layers from " << format_quantity(plan.low, "mm", 3)
              << " to " << format_quantity(plan.high, "mm", 3) << " (widened down to "
              << format_quantity(plan.floor, "mm", 3) << " or up to "
              << format_quantity(plan.ceiling, "mm", 3) << " if an edge holds), to "
              << format_quantity(plan.tolerance, "mm", 3) << ": " << plan.cost << '\n';
  const EarlierLayers earlier = earlier_layers(args.start_from, c, plan);
  if (args.log && !earlier.empty())
    *args.log << "verify: " << args.start_from.string() << " brackets h_stop at "
              << format_quantity(earlier.begin()->first, "mm", 3) << " .. "
              << format_quantity(earlier.rbegin()->first, "mm", 3)
              << ": its layers are not made again\n";
  install_interrupt_handler();
  StoppingVerification v =
      verify_stopping(args.case_file, args.sets, plan, budget, runs, args.log, earlier);
  if (v.status == "interrupted") return false;
  if (v.seconds_needed > 0.0)  // refused on the budget: the command that holds it
    v.status += ": " + this_check(args) + " --verify dem" +
                (args.thickness_tolerance.empty()
                     ? std::string()
                     : " --thickness-tolerance " + shell_word(args.thickness_tolerance)) +
                " --budget " + budget_holding(v.seconds_needed);
  if (v.bisection.steps.empty() && v.status != "done")
    record.verdict.reasons.push_back("stopping thickness not verified on the particle rung: " +
                                     v.status);
  else
    apply_stopping_verification(c, plan, v, record);
  if (!v.last_run.empty())
    record.simulation_runs.push_back(std::filesystem::absolute(v.last_run).string());
  return true;
}

// What a simulation of a drum on the particle rung or a chute on the continuum rung (on `cell`
// [m], else the case's) will cost, in words, and its seconds; none when it cannot be estimated
// (the reason in the words).
std::pair<std::optional<double>, std::string> scene_estimate(const Case& c, Solver solver,
                                                             std::optional<double> cell) {
  try {
    if (solver == Solver::dem && c.kind() == EquipmentKind::drum) {
      const DemRunEstimate e = estimate_dem_drum_run(c);
      return {e.seconds, e.text() + ", to the end of its " + format_quantity(e.run_cap, "s", 3) +
                             " of rotation (a run whose angle settles sooner stops sooner)"};
    }
    if (solver == Solver::cel && c.kind() == EquipmentKind::chute)
      if (auto e = estimate_cel_chute_run(c, cell)) return {e->seconds, e->text};
    return {std::nullopt, "its wall time cannot be estimated"};
  } catch (const InputError& e) {
    return {std::nullopt, "not with this case: " + std::string(e.what())};
  }
}

// --verify on a drum or a chute: one simulation on the rung asked by name, or by auto on the
// seed's rung (particles for drums; the continuum for chutes, on the cheapest CEL level the
// shipped bench table shows within the tolerance) when the verdict is MARGINAL and its estimate
// fits the budget; its answers stand beside the reduced ones. Otherwise a MARGINAL verdict names
// the command on the seed's rung with its estimate. Returns false when Ctrl-C stopped the run.
bool scene_verification(const VerificationRequest& args, const Case& c,
                        const std::filesystem::path& runs, DesignRecord& record) {
  const Solver seed_rule = c.kind() == EquipmentKind::drum ? Solver::dem : Solver::cel;
  Solver solver = seed_rule;
  std::vector<std::string> sets = args.sets;
  if (args.mode == "off" || args.mode == "auto") {
    if (record.verdict.status != VerdictStatus::marginal) return true;
    const double budget = parsed(args.budget, dim::time, "--budget", "10 min");
    const double tolerance = parsed(args.tolerance, dim::dimensionless, "--tolerance", "10%");
    std::string refused;  // why auto runs none
    std::optional<double> cell;
    if (seed_rule == Solver::cel) cell = chute_cell_within(tolerance, refused);
    std::string command = this_check(args);
    if (cell) command += " --set cel.cell_size=" + millimetres_setting(*cell);
    const auto [seconds, cost] = scene_estimate(c, seed_rule, cell);
    if (refused.empty() && seconds && *seconds > budget)
      refused = "beyond the budget of " + format_duration(budget);
    if (args.mode == "off" || !seconds || !refused.empty()) {
      record.verdict.reasons.push_back(
          "to settle it on the " +
          std::string(seed_rule == Solver::dem ? "particle" : "continuum") + " rung: " + command +
          " --verify " + to_string(seed_rule) +
          (seconds ? " --budget " + budget_holding(*seconds) : std::string()) +
          " (one simulation as feedflow simulate runs it, " + cost +
          (args.mode == "auto" && !refused.empty() ? "; not run by auto: " + refused
                                                   : std::string()) +
          ")");
      return true;
    }
    if (cell) sets.push_back("cel.cell_size=" + millimetres_setting(*cell));
  } else {
    solver = parse_solver(args.mode);
  }
  install_interrupt_handler();
  const SimulationVerification v =
      verify_by_simulation(args.case_file, sets, solver, runs, args.log);
  if (v.run.status == "interrupted") return false;
  apply_simulation_verification(c, v, record);
  if (v.run.done()) record.simulation_runs.push_back(std::filesystem::absolute(v.folder).string());
  return true;
}

// A cone's flow pattern inside its margin: the continuum's cone does not converge under
// refinement, so the particle rung's run at the design outlet reads it (`--verify dem`, the
// layer method in 3D); its command and estimate. Not run by auto: the run takes hours.
std::string cone_flow_pattern_command(const VerificationRequest& args, const Case& c,
                                      const DesignRecord& record) {
  const Estimate* rate = find_estimate(record.results, "mass_flow_rate");
  const double q =
      rate && std::holds_alternative<double>(rate->value) ? std::get<double>(rate->value) : 0.0;
  try {
    const DemRunEstimate e = estimate_dem_hopper_run(c, q);
    return "to settle the flow pattern on the particle rung (the continuum's cone does not "
           "converge under refinement): " +
           this_check(args) + " --verify dem --budget " + budget_holding(e.seconds) +
           " (its run at the design outlet reads the pattern by the layer method, " + e.text() +
           (args.mode == "auto" ? "; not run by auto" : "") + ")";
  } catch (const InputError& e) {
    return "the flow pattern cannot be verified on the particle rung with this case: " +
           std::string(e.what());
  }
}

}  // namespace

bool verify_design(const VerificationRequest& args, const Case& c, DesignRecord& record) {
  const std::filesystem::path& runs = args.runs;
  const Hopper* h = std::get_if<Hopper>(&c.equipment);
  if (!args.start_from.empty() && (args.mode != "dem" || c.kind() == EquipmentKind::drum))
    throw InputError("--start-from", "",
                     "only with --verify dem on a hopper or a chute (an earlier search of its "
                     "critical outlet width or stopping thickness)");
  if (!h)
    return args.mode == "dem" && c.kind() == EquipmentKind::chute
               ? stopping_verification(args, c, runs, record)
               : scene_verification(args, c, runs, record);
  if (args.mode == "dem") return dem_verification(args, c, *h, runs, record);
  const double tolerance = parsed(args.tolerance, dim::dimensionless, "--tolerance", "10%");
  const double budget = parsed(args.budget, dim::time, "--budget", "10 min");
  const bool rate_marginal = marginal_on(record, "mass_flow_rate");
  // A wedge's flow pattern is verified on the continuum with its rate (its pattern converges); a
  // cone's on the particle rung.
  const bool pattern_marginal = marginal_on(record, "flow_pattern_margin");
  const std::string again = this_check(args);
  if (pattern_marginal && !h->is_wedge())
    record.verdict.reasons.push_back(cone_flow_pattern_command(args, c, record));
  if (marginal_on(record, "critical_outlet_width") ||
      marginal_on(record, "mechanical_arching_width")) {
    // The continuum cannot arch: the particle rung verifies arching, asked for (dem) or, within
    // the budget by its estimate, by auto.
    std::string how;  // what --verify dem would run and cost, when the case allows it
    std::string command = again + " --verify dem";
    Case particles = c;
    std::vector<std::string> particle_sets = args.sets;
    if (marginal_on(record, "critical_outlet_width"))  // cohesive arches need contacts that pull
      if (auto cohesive = with_cohesive_contacts(c)) {
        particles = *cohesive;
        particle_sets.push_back("dem.cohesion=k_nc");
        command = again + " --set dem.cohesion=k_nc --verify dem";
      }
    std::optional<double> estimated;  // [s] the plan's runs
    std::string unanswered;           // why the particle rung cannot settle the marginal check
    try {
      const ArchingVerificationPlan plan = plan_arching_verification(
          particles, record,
          parsed(args.width_tolerance, dim::length, "--width-tolerance", "1 mm"));
      if (!marginal_on(record, plan.quantity))
        unanswered = "the case's DEM contacts (" + plan.law +
                     ") do not pull, so they verify interlocking arches, not the cohesive B_c";
      const ArchingVerificationCost cost = estimate_arching_verification(particles, record, plan);
      estimated = cost.seconds;
      if (args.width_tolerance != VerificationRequest{}.width_tolerance)
        command += " --width-tolerance " + shell_word(args.width_tolerance);
      command += " --budget " + budget_holding(cost.seconds);
      how = " (" + std::to_string(plan.runs) + " DEM runs with the " + plan.law +
            " law: the outlet, then a bisection on the width to " + args.width_tolerance + "; " +
            cost.text + ")";
    } catch (const InputError& e) {
      how = " (not with this case: " + std::string(e.what()) + ")";
    }
    if (args.mode == "auto" && estimated && unanswered.empty() && *estimated <= budget) {
      VerificationRequest on_particles = args;
      on_particles.sets = particle_sets;
      if (!dem_verification(on_particles, particles, *h, runs, record)) return false;
    } else {
      record.verdict.reasons.push_back(
          "arching is not verified on the continuum rung: its hypoplastic law has no cohesion and "
          "cannot arch; the particle rung can (interlocking arches with any law, cohesive ones "
          "with the seed's K_nc): " +
          command + how +
          (args.mode != "auto" || !estimated ? std::string()
           : !unanswered.empty()
               ? "; not run by auto: " + unanswered
               : "; not run by auto: beyond the budget of " + format_duration(budget) +
                     ", a --budget that holds it runs it"));
    }
  }
  const bool wedge_pattern = pattern_marginal && h->is_wedge();
  const bool wanted =
      args.mode == "cel" || (args.mode == "auto" && (rate_marginal || wedge_pattern));
  if (!wanted) {
    if (rate_marginal || wedge_pattern) {
      const RateVerificationPlan plan = plan_rate_verification(*h, tolerance, 1e9);
      const std::string command = again + " --verify auto --tolerance " +
                                  shell_word(args.tolerance) + " --budget " +
                                  budget_holding(plan.estimated_seconds);
      record.verdict.reasons.push_back(
          plan.cells_across.empty() ? "the discharge rate cannot be verified: " + plan.description
                                    : std::string(rate_marginal ? "to settle the discharge rate"
                                                                : "to settle the flow pattern") +
                                          ": " + command + " (" + plan.description + ")");
    }
    return true;
  }
  const RateVerificationPlan plan = plan_rate_verification(*h, tolerance, budget);
  if (plan.cells_across.empty()) {
    record.verdict.reasons.push_back("mass flow rate not verified: " + plan.description);
    return true;
  }
  install_interrupt_handler();
  const RateVerification v = verify_rate(args.case_file, args.sets, *h, plan, runs, args.log);
  if (v.status == "interrupted") return false;
  apply_rate_verification(c, v, record);
  if (v.status == "done")
    record.simulation_runs.push_back(std::filesystem::absolute(v.finest_run).string());
  return true;
}

}  // namespace feedflow
