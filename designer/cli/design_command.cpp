// feedflow design <case>: the designer's answer to a case file.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "designer/case/case_loader.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/cli/report_files.hpp"
#include "designer/design/design_check.hpp"
#include "designer/simulate/simulation_pictures.hpp"
#include "designer/simulate/solver_choice.hpp"
#include "designer/verify/arching_verification.hpp"
#include "designer/verify/rate_verification.hpp"
#include "designer/verify/simulation_verification.hpp"
#include "models/core/errors.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"
#include "reports/results_json.hpp"
#include "reports/text_summary.hpp"

namespace feedflow {
namespace {

struct DesignArguments {
  std::string case_file;
  CommandOptions options;
  bool report = false;
  std::vector<std::string> models;  // --model key=name
  std::string verify = "off";       // off | auto | cel | dem
  std::string budget = "10 min";
  std::string tolerance = "10%";
  std::string width_tolerance = "1 mm";
};

double parsed(const std::string& text, const Dimension& d, const char* flag, const char* example) {
  try {
    const double v = parse_quantity_as(text, d, d == dim::dimensionless);
    if (v > 0.0) return v;
  } catch (const std::invalid_argument&) {
  }
  throw InputError(flag, text, std::string("expected a positive ") + dimension_name(d) + ", e.g. " + example);
}

// Whether a finding of the verdict on `quantity` was marginal.
bool marginal_on(const DesignRecord& r, const std::string& quantity) {
  for (const auto& f : r.verdict.findings)
    if (f.quantity == quantity && f.status == VerdictStatus::marginal) return true;
  return false;
}

// --verify dem on a hopper: arching at the design outlet and the arching width by bisection on
// the particle rung. Returns false when Ctrl-C stopped the runs.
bool dem_verification(const DesignArguments& args, const Case& c, const Hopper& h,
                      const std::filesystem::path& runs, DesignRecord& record) {
  const double width_tolerance =
      parsed(args.width_tolerance, dim::length, "--width-tolerance", "1 mm");
  const double budget = parsed(args.budget, dim::time, "--budget", "10 min");
  const ArchingVerificationPlan plan = plan_arching_verification(c, record, width_tolerance);
  install_interrupt_handler();
  const ArchingVerification v =
      verify_arching(args.case_file, args.options.sets, h, plan, budget, runs,
                     args.options.human_output() ? &std::cout : nullptr);
  if (v.status == "interrupted") {
    std::cerr
        << "feedflow: interrupted; run the same command again to continue (runs made are kept in "
        << runs.string() << ")\n";
    return false;
  }
  apply_arching_verification(c, plan, v, record);
  if (v.at_design)
    record.simulation_runs.push_back(std::filesystem::absolute(v.design_run).string());
  return true;
}

// --verify on a drum or a chute: one simulation on the rung asked by name; its answers stand beside
// the reduced ones. `auto` runs none: with no measured wall time for these scenes (the shipped
// bench table has no DEM drum or chute point) no run can be planned within a budget (the seed's
// DEM drum is about 14 h), so a MARGINAL verdict names the command on the seed's rung (particles
// for drums, continuum for chutes). Returns false when Ctrl-C stopped the run.
bool scene_verification(const DesignArguments& args, const Case& c,
                        const std::filesystem::path& runs, DesignRecord& record) {
  const Solver seed_rule = c.kind() == EquipmentKind::drum ? Solver::dem : Solver::cel;
  if (args.verify == "off" || args.verify == "auto") {
    if (record.verdict.status == VerdictStatus::marginal)
      record.verdict.reasons.push_back(
          "to settle it on the " +
          std::string(seed_rule == Solver::dem ? "particle" : "continuum") +
          " rung: feedflow design " + args.case_file + " --verify " + to_string(seed_rule) +
          " (one simulation as feedflow simulate runs it; " +
          (args.verify == "auto" ? "not run by auto: " : "") +
          "its wall time is not in the shipped bench table, so no budget can plan it; its plan "
          "line states the particles or cells and the steps)");
    return true;
  }
  const Solver solver = parse_solver(args.verify);
  install_interrupt_handler();
  const SimulationVerification v =
      verify_by_simulation(args.case_file, args.options.sets, solver, runs,
                           args.options.human_output() ? &std::cout : nullptr);
  if (v.run.status == "interrupted") {
    std::cerr
        << "feedflow: interrupted; run the same command again to continue (runs made are kept in "
        << runs.string() << ")\n";
    return false;
  }
  apply_simulation_verification(c, v, record);
  if (v.run.done()) record.simulation_runs.push_back(std::filesystem::absolute(v.folder).string());
  return true;
}

// --verify: the hopper's rate on the continuum rung when asked (cel) or when its decision is
// inside its band (auto), its arching on the particle rung (dem); without --verify, a MARGINAL
// says what would settle it; drums and chutes by scene_verification. Returns false when Ctrl-C
// stopped the runs.
bool verification(const DesignArguments& args, const Case& c, const std::filesystem::path& runs, DesignRecord& record) {
  const Hopper* h = std::get_if<Hopper>(&c.equipment);
  if (!h) return scene_verification(args, c, runs, record);
  if (args.verify == "dem") return dem_verification(args, c, *h, runs, record);
  const double tolerance = parsed(args.tolerance, dim::dimensionless, "--tolerance", "10%");
  const double budget = parsed(args.budget, dim::time, "--budget", "10 min");
  const bool rate_marginal = marginal_on(record, "mass_flow_rate");
  const auto quoted = [](const std::string& a) {
    return a.find(' ') == std::string::npos ? a : "\"" + a + "\"";
  };
  std::string again = "feedflow design " + quoted(args.case_file);  // this check, as typed
  for (const auto& set : args.options.sets) again += " --set " + quoted(set);
  if (marginal_on(record, "critical_outlet_width") ||
      marginal_on(record, "mechanical_arching_width")) {
    std::string how;  // what --verify dem would run, when the case allows it
    std::string command = again + " --verify dem";
    Case particles = c;
    if (marginal_on(record, "critical_outlet_width"))  // cohesive arches need contacts that pull
      if (auto cohesive = with_cohesive_contacts(c)) {
        particles = *cohesive;
        command = again + " --set dem.cohesion=k_nc --verify dem";
      }
    try {
      const ArchingVerificationPlan plan = plan_arching_verification(
          particles, record,
          parsed(args.width_tolerance, dim::length, "--width-tolerance", "1 mm"));
      how = " (" + std::to_string(plan.runs) + " DEM runs with the " + plan.law +
            " law: the outlet, then a bisection on the width to " + args.width_tolerance + ")";
    } catch (const InputError& e) {
      how = " (not with this case: " + std::string(e.what()) + ")";
    }
    record.verdict.reasons.push_back(
        "arching is not verified on the continuum rung: its hypoplastic law has no cohesion and "
        "cannot arch; the particle rung can (interlocking arches with any law, cohesive ones with "
        "the seed's K_nc): " +
        command + how);
  }
  const bool wanted = args.verify == "cel" || (args.verify == "auto" && rate_marginal);
  if (!wanted) {
    if (rate_marginal) {
      const RateVerificationPlan plan = plan_rate_verification(*h, tolerance, 1e9);
      const std::string command = again + " --verify auto --tolerance " + quoted(args.tolerance) +
                                  " --budget " +
                                  format_number(std::ceil(plan.estimated_seconds / 60.0 * 1.2), 3) +
                                  "min";
      record.verdict.reasons.push_back(plan.cells_across.empty()
                                           ? "the discharge rate cannot be verified: " + plan.description
                                           : "to settle the discharge rate: " + command + " (" + plan.description + ")");
    }
    return true;
  }
  const RateVerificationPlan plan = plan_rate_verification(*h, tolerance, budget);
  if (plan.cells_across.empty()) {
    record.verdict.reasons.push_back("mass flow rate not verified: " + plan.description);
    return true;
  }
  install_interrupt_handler();
  const RateVerification v = verify_rate(args.case_file, args.options.sets, *h, plan, runs,
                                         args.options.human_output() ? &std::cout : nullptr);
  if (v.status == "interrupted") {
    std::cerr << "feedflow: interrupted; run the same command again to continue (runs made are kept in "
              << runs.string() << ")\n";
    return false;
  }
  apply_rate_verification(c, v, record);
  if (v.status == "done")
    record.simulation_runs.push_back(std::filesystem::absolute(v.finest_run).string());
  return true;
}

int run_design(const DesignArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<SetOverride> overrides;
  for (const auto& s : args.options.sets) overrides.push_back(parse_set_override(s));

  const ModelChoices models = ModelChoices::parse(args.models);
  const Case c = load_case(args.case_file, overrides);
  if (!args.options.quiet)
    for (const auto& w : c.warnings) std::cerr << "feedflow: warning: " << w << '\n';
  if (args.options.verbose)
    std::cerr << "feedflow: material " << c.material.name << " from " << c.material.origin << '\n';

  DesignRecord record = design_check(c, models);
  const std::filesystem::path verify_runs =
      (args.options.out.empty() ? std::filesystem::path("out") / (safe_folder_name(c.name) + "_verify")
                                : std::filesystem::path(args.options.out) / "verify");
  if (!verification(args, c, verify_runs, record)) return kExitInterrupted;
  record.command_line = invocation();
  record.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const auto folder = output_folder(args.options, c.name, "", args.report);
  if (folder)  // the runs as seen from the results file, so the folder can move with them
    for (auto& run : record.simulation_runs)
      run = std::filesystem::absolute(run)
                .lexically_relative(std::filesystem::absolute(*folder))
                .string();
  const std::string summary = text_summary(record);
  const std::string json = to_json(record).dump(2) + "\n";
  auto files = results_files(folder, json, summary, args.options);
  if (args.report)
    for (auto& file : report_files(*folder, record, record_pictures(record, *folder, std::cerr)))
      files.push_back(std::move(file));
  std::optional<OutputFolder> claimed;
  if (folder) claimed.emplace(*folder, "--out");
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json : nullptr,
                                     args.options.verbose, claimed ? &*claimed : nullptr);

  if (args.options.human_output()) {
    std::cout << summary << "\nWritten: ";
    for (std::size_t i = 0; i < written.size(); ++i)
      std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
  return verdict_exit_code(args.options, record.verdict.status);
}

}  // namespace

void add_design_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<DesignArguments>();
  auto* command = app.add_subcommand(
      "design", "answer the design questions of a case from the reduced models");
  command->add_option("case", args->case_file, "case file (TOML), e.g. cases/pilot_hopper.toml")
      ->required()
      ->type_name("CASE");
  add_case_options(*command, args->options,
                   "out/<case name>; none with --json - unless --report asks for one");
  command->add_flag("--report", args->report, "also write report.pdf and report.html");
  command
      ->add_option(
          "--verify", args->verify,
          "verify on a full rung: auto (the quantities whose decision is inside their band, on "
          "the seed's rung), cel (a hopper's discharge rate; a chute's or drum's answers from one "
          "continuum run), dem (a hopper's arching: at the outlet, and the critical width by "
          "bisection; a drum's or chute's answers from one particle run), off")
      ->capture_default_str()
      ->check(CLI::IsMember({"off", "auto", "cel", "dem"}))
      ->type_name("RUNG");
  command->add_option("--budget", args->budget, "wall time a verification may take")
      ->capture_default_str()
      ->type_name("TIME");
  command->add_option("--tolerance", args->tolerance, "error bar a verification must reach")
      ->capture_default_str()
      ->type_name("FRACTION");
  command
      ->add_option("--width-tolerance", args->width_tolerance,
                   "--verify dem: width of the bracket the bisection on the outlet width stops at")
      ->capture_default_str()
      ->type_name("WIDTH");
  std::string model_help = "select an alternative model (repeatable):";
  for (const auto& o : model_options()) {
    model_help += "\n  " + std::string(o.key) + "=";
    for (std::size_t i = 0; i < o.entries.size(); ++i)
      model_help += (i ? "|" : "") + std::string(o.entries[i].name);
    model_help += " (" + std::string(o.description) + ", default " + std::string(o.entries.front().name) + ")";
    for (const auto& e : o.entries)
      model_help += "\n      " + std::string(e.name) + ": " + std::string(e.summary) + " [" + to_string(e.rung) + "]";
  }
  command->add_option("--model", args->models, model_help)
      ->type_name("KEY=NAME")
      ->take_all()
      ->allow_extra_args(false);
  command->callback([args, &exit_code] { exit_code = run_design(*args); });
}

}  // namespace feedflow
