// feedflow calibrate MATERIAL --against cel|dem: fits the reduced models' free coefficients to
// full-rung results over a design of experiments, and writes them into the material file: for a
// hopper case the discharge models' coefficients over outlet width x semi-angle ([calibration]),
// for a drum case the flowing layer over drum speeds ([calibration.drum]), for an inclined-plane
// case Pouliquen's h_stop law over the inclination ([calibration.chute]); some points held out.
// Runs are made through the bench's machinery and kept in the output folder: a repeated or
// interrupted calibration reads back what is done.
#include <chrono>
#include <iostream>
#include <memory>

#include "designer/bench/bench_run.hpp"
#include "designer/calibrate/arching_report.hpp"
#include "designer/calibrate/calibration_design.hpp"
#include "designer/calibrate/calibration_report.hpp"
#include "designer/calibrate/chute_calibration_report.hpp"
#include "designer/calibrate/drum_calibration_report.hpp"
#include "designer/calibrate/stopping_records.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/case/material_library.hpp"
#include "designer/case/material_text.hpp"
#include "designer/cli/calibration_runs.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/output_folder.hpp"
#include "designer/design/drum_check.hpp"
#include "models/core/commit.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

using namespace calibrate_cli;

// "45 mm@25 deg,75 mm@25 deg".
std::vector<DesignPoint> held_out_points(const std::string& text) {
  std::vector<DesignPoint> out;
  if (text.empty() || text == "none") return out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto at = item.find('@');
    if (at == std::string::npos)
      throw InputError("--held-out", item, "expected WIDTH@ANGLE, e.g. \"45 mm@25 deg\"");
    try {
      out.push_back({parse_quantity_as(item.substr(0, at), dim::length, false),
                     parse_quantity_as(item.substr(at + 1), dim::angle, false), true});
    } catch (const std::invalid_argument& e) {
      throw InputError("--held-out", item, e.what());
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

CalibrationDesign design_of(const CalibrateArguments& args) {
  CalibrationDesign d;
  d.case_file = args.case_file;
  d.material = args.material;
  d.against = args.against;
  d.points = grid_points(quantity_list(args.outlet_widths, dim::length, "--outlet-widths"),
                         quantity_list(args.semi_angles, dim::angle, "--semi-angles"), held_out_points(args.held_out));
  d.cells_across = args.cells_across;
  d.order = args.order;
  if (!args.time.empty()) {
    try {
      d.time = parse_quantity_as(args.time, dim::time, false);
    } catch (const std::invalid_argument& e) {
      throw InputError("--time", args.time, e.what());
    }
  }
  d.check();
  return d;
}

// Every point's case, loaded before any run (a typo in --case, a width the case refuses).
std::vector<Case> point_cases(const CalibrationOutcome& o) {
  std::vector<Case> cases;
  for (const auto& p : o.points) {
    std::vector<SetOverride> overrides;
    for (const auto& s : p.question.sets) overrides.push_back(parse_set_override(s));
    cases.push_back(load_case(o.design.case_file, overrides));
    if (!std::holds_alternative<Hopper>(cases.back().equipment))
      throw InputError("--case", o.design.case_file, "a discharge calibration needs a hopper case");
  }
  return cases;
}

int run_hopper_calibration(const CalibrateArguments& args,
                           std::chrono::steady_clock::time_point start) {
  CalibrationOutcome o;
  o.design = design_of(args);
  const Material material = calibrated_material(args);
  o.material = material.name;
  for (const auto& p : o.design.points) o.points.push_back({design_point_question(o.design, p), {}, "done"});
  if (args.list) {
    list_runs(o.points);
    return kExitOk;
  }
  const std::vector<Case> cases = point_cases(o);
  const std::filesystem::path out = output_folder(args, material);
  OutputFolder folder(out, "--out");
  if (!run_points(args, out, o)) return kExitInterrupted;
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    if (o.points[i].status != "done") continue;
    o.observations.push_back({std::get<Hopper>(cases[i].equipment), *o.points[i].reference.value,
                              o.points[i].reference.error_bar.value_or(0.0), o.design.points[i].held_out});
    o.observed.push_back(i);
  }
  const auto fitted = std::count_if(o.observations.begin(), o.observations.end(),
                                    [](const DischargeObservation& x) { return !x.held_out; });
  require_two_fitted(fitted, "point(s) have a reference rate", out);
  // The reduced models are evaluated with the material the runs used: the case's.
  const HopperDensityModel& density = hopper_density_models().default_row();
  o.fit = fit_discharge(o.observations, HopperMaterial::of(cases.front().material, density));
  const Calibration table =
      calibration_table(o, cases.front().name, std::get<Hopper>(cases.front().equipment).is_wedge(),
                        std::string(density.name), commit_text(kCommit, o.run_commits), today());
  const auto target = material_target(args, material, out);
  write_calibration(
      args, calibration_json(o, table), out, target,
      with_calibration(material_text(material),
                       calibration_toml(table, calibration_point_records(o)),
                       CalibrationPart::hopper),
      folder, calibration_summary(o, table) + runs_text(o.runs_made, o.runs_read_back), start);
  return kExitOk;
}

DrumCalibrationDesign drum_design_of(const CalibrateArguments& args, const Case& drum_case,
                                     const Material& material) {
  DrumCalibrationDesign d;
  d.case_file = args.case_file;
  if (drum_case.material.name != material.name) d.material = args.material;
  d.against = args.against;
  d.points = speed_points(quantity_list(args.speeds, dim::angular_speed, "--speeds"),
                          held_out_list(args, dim::angular_speed, kDrumHeldOut));
  d.finest_cell = finest_cell(args, "5mm");
  d.check();
  return d;
}

// Each point's drum, checked to roll by the material's thresholds: the angle model's domain.
std::vector<Case> drum_point_cases(const DrumCalibrationOutcome& o) {
  std::vector<Case> cases;
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    std::vector<SetOverride> overrides;
    for (const auto& s : o.points[i].question.sets) overrides.push_back(parse_set_override(s));
    cases.push_back(load_case(o.design.case_file, overrides));
    const Case& c = cases.back();
    const Drum& drum = std::get<Drum>(c.equipment);
    if (!c.material.drum_flow || !c.material.surface_flow)
      throw InputError(c.material.origin, "material.drum_flow",
                       "a drum calibration needs the material's [drum_flow] and [surface_flow]");
    const DrumRegimeAssessment regime =
        assess_drum_regime(drum, regime_thresholds(*c.material.drum_flow));
    if (regime.regime != DrumRegime::Rolling)
      throw InputError(
          o.design.points[i].held_out ? "--held-out" : "--speeds", rpm_text(drum.speed) + " rpm",
          "a speed where the drum rolls: the angle model holds in the rolling regime only, and " +
              c.material.name + "'s thresholds make this drum " +
              std::string(to_string(regime.regime)) +
              " there (Fr = " + format_number(regime.froude, 3) + ")");
  }
  return cases;
}

int run_drum_calibration(const CalibrateArguments& args, const Case& drum_case,
                         std::chrono::steady_clock::time_point start) {
  const Material material = calibrated_material(args);
  DrumCalibrationOutcome o;
  o.design = drum_design_of(args, drum_case, material);
  o.material = material.name;
  for (const auto& p : o.design.points)
    o.points.push_back({drum_point_question(o.design, p), {}, "done"});
  const std::vector<Case> cases = drum_point_cases(o);
  if (args.list) {
    list_runs(o.points);
    return kExitOk;
  }
  const std::filesystem::path out = output_folder(args, material);
  OutputFolder folder(out, "--out");
  if (!run_points(args, out, o)) return kExitInterrupted;
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    if (o.points[i].status != "done") continue;
    // The bench's angles are in degrees.
    const BenchReference& r = o.points[i].reference;
    o.observations.push_back({std::get<Drum>(cases[i].equipment), *r.value * kDegree,
                              r.error_bar.value_or(0.0) * kDegree, o.design.points[i].held_out});
    o.observed.push_back(i);
  }
  const auto fitted = std::count_if(o.observations.begin(), o.observations.end(),
                                    [](const DrumObservation& x) { return !x.held_out; });
  require_two_fitted(fitted, "speed(s) have a reference angle", out);
  o.fit = fit_drum_layer(o.observations, cases.front().material, o.design.against == "dem");
  // A layer that could not be fitted is not written: the material keeps what it had.
  if (!o.fit.failure.empty())
    throw NumericalFailure(
        "calibration: the drum's flowing layer could not be fitted (" + o.fit.failure +
        "); the material file is left as it was; see the runs in " + (out / "runs").string());
  const DrumCalibration table =
      drum_calibration_table(o, cases.front().name, std::get<Drum>(cases.front().equipment),
                             commit_text(kCommit, o.run_commits), today());
  const auto target = material_target(args, material, out);
  write_calibration(
      args, drum_calibration_json(o, table), out, target,
      with_calibration(material_text(material), drum_calibration_toml(table, drum_point_records(o)),
                       CalibrationPart::drum),
      folder, drum_calibration_summary(o, table) + runs_text(o.runs_made, o.runs_read_back), start);
  return kExitOk;
}

// The arching models' strength fitted to the critical outlet widths of verified design records:
// no runs are made here (each bracket is a bisection of its own, made and kept by `design
// --verify dem --width-tolerance`).
int run_arching_calibration(const CalibrateArguments& args, const Case& hopper_case,
                            std::chrono::steady_clock::time_point start) {
  const Material material = calibrated_material(args);
  if (hopper_case.material.name != material.name)
    throw InputError("--case", args.case_file,
                     "a hopper case of " + material.name + " (its material is " +
                         hopper_case.material.name + ")");
  const std::vector<double> held_out = held_out_list(args, dim::angle);
  ArchingCalibrationOutcome o;
  o.material = material.name;
  o.against = args.against;
  o.scene = hopper_case.name;
  o.flow_factor = std::string(flow_factor_models().default_row().name);
  std::set<std::string> commits;
  for (const auto& file : args.arching) {
    ArchingRecord r = read_arching_record(file, args.against, material.name,
                                          std::get<Hopper>(hopper_case.equipment));
    for (double angle : held_out)
      if (std::abs(angle - r.observation.hopper.semi_angle) < 1e-6) r.observation.held_out = true;
    if (!o.records.empty() && r.rung != o.records.front().rung)
      throw InputError(file, "results.critical_outlet_width.model",
                       "expected the rung of the other records (" + o.records.front().rung +
                           "), got " + r.rung);
    commits.insert(r.commits.begin(), r.commits.end());
    o.records.push_back(std::move(r));
  }
  std::vector<ArchingObservation> observations;
  for (const auto& r : o.records) observations.push_back(r.observation);
  try {
    o.fit = fit_arching(observations, HopperMaterial::of(hopper_case.material));
  } catch (const std::invalid_argument& e) {
    throw InputError("--arching", args.arching.front(), e.what());
  }
  if (args.list) {
    for (const auto& r : o.records) std::cout << r.file.string() << ": " << r.bracket << '\n';
    return kExitOk;
  }
  const std::filesystem::path out = output_folder(args, material);
  OutputFolder folder(out, "--out");
  const ArchingCalibration table =
      arching_calibration_table(o, commit_text(kCommit, commits), today());
  const auto target = material_target(args, material, out);
  write_calibration(args, arching_calibration_json(o, table), out, target,
                    with_calibration(material_text(material),
                                     arching_calibration_toml(table, arching_point_records(o)),
                                     CalibrationPart::arching),
                    folder, arching_calibration_summary(o, table), start);
  return kExitOk;
}

ChuteCalibrationDesign chute_design_of(const CalibrateArguments& args, const Case& plane_case,
                                       const Material& material) {
  ChuteCalibrationDesign d;
  d.case_file = args.case_file;
  if (plane_case.material.name != material.name) d.material = args.material;
  d.against = args.against;
  d.points = inclination_points(quantity_list(args.angles, dim::angle, "--angles"),
                                held_out_list(args, dim::angle));
  d.finest_cell = finest_cell(args, "10mm");
  d.check();
  return d;
}

// The plane's inclinations from verified design records (--stopping): no runs are made here,
// each bracket is a bisection of its own, made and kept by `design --verify dem`.
void observe_stopping_records(const CalibrateArguments& args, const Material& material,
                              ChuteCalibrationOutcome& o) {
  if (args.against != "dem")
    throw InputError("--against", args.against,
                     "dem with --stopping (its records are h_stop brackets of `design --verify "
                     "dem`; against cel the calibration runs the plane's CEL series itself)");
  const std::vector<double> held_out = held_out_list(args, dim::angle);
  std::vector<StoppingRecord> records;
  for (const auto& file : args.stopping) {
    StoppingRecord r = read_stopping_record(file, material.name);
    for (double angle : held_out)
      if (std::abs(angle - r.observation.angle) < 1e-6) r.observation.held_out = true;
    for (const auto& other : records) {
      if (std::abs(other.observation.angle - r.observation.angle) < 1e-9)
        throw InputError(
            file, "inputs.chute.angle",
            "each inclination once: " + format_quantity(r.observation.angle, "deg", 4) +
                " is also " + other.file.string() + "'s");
      if (other.rung != r.rung)
        throw InputError(file, "results.stopping_thickness.model",
                         "expected the rung of the other records (" + other.rung + "), got " +
                             r.rung);
    }
    records.push_back(std::move(r));
  }
  for (double angle : held_out)
    if (std::none_of(records.begin(), records.end(), [&](const StoppingRecord& r) {
          return std::abs(angle - r.observation.angle) < 1e-6;
        }))
      throw InputError("--held-out", format_quantity(angle, "deg", 4),
                       "the angle of one of the --stopping records");
  if (std::count_if(records.begin(), records.end(),
                    [](const StoppingRecord& r) { return !r.observation.held_out; }) < 2)
    throw InputError("--stopping", std::to_string(records.size()) + " record(s)",
                     "a chute calibration fits theta2 and L: records at two inclinations at "
                     "least, not held out");
  o.design.against = "dem";
  o.rung = records.front().rung + ", read from verified designs";
  for (const auto& r : records) {
    o.design.points.push_back({r.observation.angle, r.observation.held_out});
    CalibrationPoint point;
    point.question.title = r.file.string();
    point.reference.value = r.observation.reference;
    point.reference.error_bar = r.observation.error_bar;
    point.reference.unit = "m";
    point.reference.source = "rests at " + format_quantity(r.stops_at, "mm", 4) + ", flows at " +
                             format_quantity(r.flows_at, "mm", 4) +
                             (r.so_far ? ", its search cut short" : "") + " (" + r.command + ")";
    o.points.push_back(std::move(point));
    o.observed.push_back(o.observations.size());
    o.observations.push_back(r.observation);
    o.run_commits.insert(r.commits.begin(), r.commits.end());
  }
}

// The plane's inclinations, each run on the rung (or read back from OUT/runs); false when Ctrl-C
// stopped the runs.
bool observe_plane_runs(const CalibrateArguments& args, const std::filesystem::path& out,
                        ChuteCalibrationOutcome& o) {
  if (!run_points(args, out, o, keep_resolving_levels)) return false;
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    if (o.points[i].status != "done") continue;
    const BenchReference& r = o.points[i].reference;
    const double metres = parse_quantity_as("1 " + r.unit, dim::length, false);
    o.observations.push_back({o.design.points[i].angle, *r.value * metres,
                              r.error_bar.value_or(0.0) * metres, o.design.points[i].held_out});
    o.observed.push_back(i);
  }
  const auto fitted = std::count_if(o.observations.begin(), o.observations.end(),
                                    [](const StopObservation& x) { return !x.held_out; });
  require_two_fitted(fitted, "inclination(s) have a reference deposit", out);
  return true;
}

// Pouliquen's h_stop law (theta2 and L; theta1 too from three inclinations) fitted to the rung's
// deposits over the plane's inclination: its runs made here, or the brackets of verified designs.
int run_chute_calibration(const CalibrateArguments& args, const Case& plane_case,
                          std::chrono::steady_clock::time_point start) {
  const Material material = calibrated_material(args);
  if (!material.surface_flow)
    throw InputError(material.origin, "material.surface_flow",
                     "a chute calibration needs the material's [surface_flow] (theta1 is held)");
  ChuteCalibrationOutcome o;
  o.material = material.name;
  const bool from_records = !args.stopping.empty();
  if (from_records) {
    o.design.case_file = args.case_file;
    observe_stopping_records(args, material, o);
    if (args.list) {
      for (const auto& p : o.points)
        std::cout << p.question.title << ": " << p.reference.source << '\n';
      return kExitOk;
    }
  } else {
    o.design = chute_design_of(args, plane_case, material);
    for (const auto& p : o.design.points)
      o.points.push_back({chute_point_question(o.design, p), {}, "done"});
    for (const auto& p : o.points) {  // every point's case, before any run
      std::vector<SetOverride> overrides;
      for (const auto& s : p.question.sets) overrides.push_back(parse_set_override(s));
      (void)load_case(o.design.case_file, overrides);
    }
    if (args.list) {
      list_runs(o.points);
      return kExitOk;
    }
  }
  const std::filesystem::path out = output_folder(args, material);
  OutputFolder folder(out, "--out");
  if (!from_records && !observe_plane_runs(args, out, o)) return kExitInterrupted;
  o.fit = fit_stop_law(o.observations, material);
  // A law that could not be fitted is not written: the material keeps what it had.
  if (!o.fit.failure.empty())
    throw NumericalFailure(
        "calibration: the stopping-thickness law could not be fitted (" + o.fit.failure +
        "); the material file is left as it was" +
        (from_records ? std::string() : "; see the runs in " + (out / "runs").string()));
  const ChuteCalibration table =
      chute_calibration_table(o, plane_case.name, commit_text(kCommit, o.run_commits), today());
  const auto target = material_target(args, material, out);
  write_calibration(args, chute_calibration_json(o, table), out, target,
                    with_calibration(material_text(material),
                                     chute_calibration_toml(table, chute_point_records(o)),
                                     CalibrationPart::chute),
                    folder,
                    chute_calibration_summary(o, table) +
                        (from_records ? std::to_string(o.points.size()) +
                                            " verified design(s) read, no run made\n"
                                      : runs_text(o.runs_made, o.runs_read_back)),
                    start);
  return kExitOk;
}

// A hopper case calibrates the discharge (or, with --arching, the arching models), a drum case
// the flowing layer, an inclined-plane case the stopping-thickness law.
int run_calibrate(const CalibrateArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  const Case c = load_case(args.case_file, {});
  if (!args.arching.empty()) {
    if (!std::holds_alternative<Hopper>(c.equipment))
      throw InputError("--case", args.case_file,
                       "a hopper case (--arching fits the hopper's arching models)");
    return run_arching_calibration(args, c, start);
  }
  if (!args.stopping.empty() && !std::holds_alternative<Chute>(c.equipment))
    throw InputError("--case", args.case_file,
                     "an inclined-plane case (--stopping fits its stopping-thickness law)");
  if (std::holds_alternative<Drum>(c.equipment)) return run_drum_calibration(args, c, start);
  if (std::holds_alternative<Chute>(c.equipment)) return run_chute_calibration(args, c, start);
  if (!std::holds_alternative<Hopper>(c.equipment))
    throw InputError("--case", args.case_file,
                     "a hopper case (discharge), a drum case (flowing layer) or an inclined-plane "
                     "case (stopping thickness)");
  return run_hopper_calibration(args, start);
}

}  // namespace

void add_calibrate_command(Command& program, int& exit_code) {
  auto args = std::make_shared<CalibrateArguments>();
  auto command = program.subcommand("calibrate",
                                    "fit the reduced models' coefficients to a full rung over a "
                                    "design of experiments (hopper: discharge; drum: "
                                    "flowing layer; inclined plane: stopping thickness)");
  command.option("material", args->material, "the material to calibrate (see `feedflow materials`)")
      .required();
  command.option("--against", args->against, "the full rung to fit to")
      .required()
      .one_of({"cel", "dem"});
  command
      .option("--case", args->case_file,
              "the case varied: a hopper's outlet and semi-angle, a drum's speed, or an inclined "
              "plane's angle")
      .show_default()
      .type_name("FILE");
  command.option("--outlet-widths", args->outlet_widths, "outlet widths of the fitted grid")
      .show_default()
      .type_name("LIST");
  command.option("--semi-angles", args->semi_angles, "semi-angles of the fitted grid")
      .show_default()
      .type_name("LIST");
  command
      .option("--held-out", args->held_out,
              std::string(
                  "points left out of the fit to test it: a hopper's WIDTH@ANGLE,... (default ") +
                  kHopperHeldOut + "), a drum's speeds (default " + kDrumHeldOut +
                  "), a plane's angles (default none), --arching's semi-angles (default none); "
                  "none")
      .type_name("LIST");
  command.option("--speeds", args->speeds, "a drum's fitted speeds, where it rolls")
      .show_default()
      .type_name("LIST");
  command
      .option("--angles", args->angles, "an inclined plane's fitted angles, each leaving a deposit")
      .show_default()
      .type_name("LIST");
  command
      .option("--finest-cell", args->finest_cell,
              "a drum's or a plane's finest CEL level (the refinement series from 20 mm down to "
              "it; default 5 mm for a drum, 10 mm for a plane)")
      .type_name("LENGTH");
  command
      .option("--cells-across", args->cells_across,
              "CEL levels: cells across the half outlet, each twice the last (Richardson)")
      .delimiter(',')
      .show_default()
      .type_name("N[,N...]");
  command.option(
      "--order", args->order,
      "order two CEL levels extrapolate with (default: the order in the shipped bench table)");
  command
      .option("--time", args->time,
              "simulated time of each run after the opening (as the bench measured)")
      .show_default()
      .type_name("TIME");
  command
      .option("--write", args->write,
              "material file to write (default: the material's own file; a built-in material: "
              "OUT/<name>.toml)")
      .type_name("FILE");
  command
      .option("--arching", args->arching,
              "fit the arching models' strength (sigma_c scale) to the critical outlet widths of "
              "these verified designs (results.json of `design --verify dem --width-tolerance "
              "...`) instead of the discharge; --held-out then takes semi-angles")
      .type_name("RESULTS...");
  command
      .option("--stopping", args->stopping,
              "fit an inclined plane's stopping-thickness law to the h_stop brackets of these "
              "verified designs (results.json of `design PLANE --set chute.angle=ANGLE --verify "
              "dem`, one per angle) instead of running --angles; --held-out then picks among "
              "their angles")
      .type_name("RESULTS...");
  command.flag("--list", args->list, "list the runs the calibration makes, then stop");
  command
      .option("--out", args->options.out,
              "output folder (default out/calibrate/<material>); runs already in it are read back")
      .type_name("DIR");
  add_json_option(command, args->options, "the calibration JSON");
  add_verbosity_options(command, args->options, true);
  command.on_run([args, &exit_code] { exit_code = run_calibrate(*args); });
}

}  // namespace feedflow
