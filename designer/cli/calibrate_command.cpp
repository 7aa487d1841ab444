// feedflow calibrate MATERIAL --against cel|dem: fits the hopper discharge models' free
// coefficients to full-rung rates over a design of experiments (outlet width x semi-angle of a
// hopper case, some points held out), and writes them into the material file as [calibration].
// Runs are made through the bench's machinery and kept in the output folder: a repeated or
// interrupted calibration reads back what is done.
#include <chrono>
#include <ctime>
#include <iostream>
#include <memory>

#include "designer/bench/bench_run.hpp"
#include "designer/bench/bench_table.hpp"
#include "designer/calibrate/calibration_design.hpp"
#include "designer/calibrate/calibration_report.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/case/material_library.hpp"
#include "designer/case/material_text.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/cli/output_folder.hpp"
#include "models/core/commit.hpp"
#include "models/core/errors.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_list.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

struct CalibrateArguments {
  std::string material;
  std::string against;
  std::string case_file = "cases/pilot_hopper.toml";
  // The design measured on the pilot hopper: 12 CEL runs, about 40 min on 2 cores (W 40 mm at
  // 15 deg alone would take about 30 min at 6 cells across the half outlet).
  std::string outlet_widths = "50,100 mm";
  std::string semi_angles = "20,35 deg";
  std::string held_out = "60 mm@30 deg,75 mm@25 deg";
  std::vector<double> cells_across = {3.0, 6.0};
  std::optional<double> order;
  std::string time = "1s";  // after the opening, as the bench measured the hopper's rate
  std::string write;
  bool list = false;
  CommandOptions options;
};

std::vector<double> quantity_list(const std::string& text, const Dimension& d, const char* flag) {
  try {
    return parse_quantity_list(text, d);
  } catch (const std::invalid_argument& e) {
    throw InputError(flag, text, e.what());
  }
}

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

std::string today() {
  const std::time_t now = std::time(nullptr);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
  return text;
}

// Each point's runs, made or read back, and its reference; false when Ctrl-C stopped them.
bool make_runs(const CalibrateArguments& args, const std::filesystem::path& runs_root, CalibrationOutcome& o) {
  const bool say = args.options.human_output();
  std::size_t total = 0, k = 0;
  for (const auto& p : o.points) total += p.question.points.size();
  for (auto& point : o.points) {
    std::map<std::string, BenchRun> runs;
    for (const auto& bp : point.question.points) {
      ++k;
      const auto folder = bench_run_folder(runs_root, point.question, bp);
      if (say && !saved_run_of(point.question, bp, ".", folder))
        std::cout << "[" << k << "/" << total << "] " << point.question.title << ": " << bp.setting << " ..." << std::flush;
      bool was_made = false;
      BenchRun run = run_or_read_back(point.question, bp, ".", folder, was_made);
      if (was_made) {
        ++o.runs_made;
        if (say) std::cout << " " << format_number(run.wall_seconds, 3) << " s" << (run.done() ? "" : " (" + run.status + ")") << '\n';
        if (run.status == "interrupted" || interrupt_requested()) return false;
      } else {
        ++o.runs_read_back;
      }
      if (!run.done()) point.status = run.status;
      o.run_commits.insert(run.commit);
      runs[point_id(bp)] = std::move(run);
    }
    point.reference = tabulate(point.question, runs).reference;
    const BenchReference& r = point.reference;
    if (point.status != "done") continue;
    if (!r.value || !(*r.value > 0.0)) point.status = "no reference rate";
    else if (r.error_bar && *r.error_bar > kUsableUncertainty * *r.value)
      point.status = "reference too uncertain (" + format_number(*r.value, 3) + " +- " + format_number(*r.error_bar, 2) +
                     " kg/s)";
  }
  return true;
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

int run_calibrate(const CalibrateArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  CalibrationOutcome o;
  o.design = design_of(args);
  const Material material =
      MaterialLibrary::standard(std::filesystem::path(args.case_file).parent_path()).load(args.material);
  o.material = material.name;
  for (const auto& p : o.design.points) o.points.push_back({design_point_question(o.design, p), {}, "done"});
  if (args.list) {
    for (const auto& p : o.points)
      for (const auto& bp : p.question.points) std::cout << bench_invocation(p.question, bp) << '\n';
    return kExitOk;
  }
  const std::vector<Case> cases = point_cases(o);
  const std::filesystem::path out =
      args.options.out.empty() ? std::filesystem::path("out/calibrate") / file_name_friendly(material.name)
                               : std::filesystem::path(args.options.out);
  OutputFolder folder(out, "--out");
  install_interrupt_handler();
  if (!make_runs(args, out / "runs", o)) {
    std::cerr << continue_after_interrupt(out / "runs");
    return kExitInterrupted;
  }
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    if (o.points[i].status != "done") continue;
    o.observations.push_back({std::get<Hopper>(cases[i].equipment), *o.points[i].reference.value,
                              o.points[i].reference.error_bar.value_or(0.0), o.design.points[i].held_out});
    o.observed.push_back(i);
  }
  const auto fitted = std::count_if(o.observations.begin(), o.observations.end(),
                                    [](const DischargeObservation& x) { return !x.held_out; });
  if (fitted < 2)
    throw NumericalFailure("calibration: only " + std::to_string(fitted) +
                           " fitted point(s) have a reference rate; see the runs in " + (out / "runs").string());
  // The reduced models are evaluated with the material the runs used: the case's.
  const HopperDensityModel& density = hopper_density_models().default_row();
  o.fit = fit_discharge(o.observations, HopperMaterial::of(cases.front().material, density));
  const Calibration table =
      calibration_table(o, cases.front().name, std::get<Hopper>(cases.front().equipment).is_wedge(),
                        std::string(density.name), commit_text(kCommit, o.run_commits), today());

  // The material file: the one it came from, or a copy beside the runs for a built-in material.
  const std::filesystem::path target = !args.write.empty()            ? std::filesystem::path(args.write)
                                       : material.origin != "built-in" ? std::filesystem::path(material.origin)
                                                                       : out / (file_name_friendly(material.name) + ".toml");
  nlohmann::ordered_json j = calibration_json(o, table);
  j["command_line"] = invocation();
  j["material_file"] = target.string();
  j["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string json_text = j.dump(2) + "\n";
  std::vector<OutputFile> files = {
      {out / "calibration.json", json_text, "--out"},
      {target, with_calibration(material_text(material), calibration_toml(table, calibration_point_records(o))), "--write"}};
  if (!args.options.json.empty() && !args.options.json_to_stdout()) files.push_back({args.options.json, json_text, "--json"});
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json_text : nullptr, args.options.verbose, &folder);
  if (args.options.human_output()) {
    std::cout << calibration_summary(o, table) << o.runs_made << " run(s) made, " << o.runs_read_back
              << " read back\nWritten: ";
    for (std::size_t i = 0; i < written.size(); ++i) std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
  return kExitOk;
}

}  // namespace

void add_calibrate_command(Command& program, int& exit_code) {
  auto args = std::make_shared<CalibrateArguments>();
  auto command = program.subcommand(
      "calibrate",
      "fit the reduced models' discharge coefficients to a full rung over a design of experiments");
  command.option("material", args->material, "the material to calibrate (see `feedflow materials`)")
      .required();
  command.option("--against", args->against, "the full rung to fit to")
      .required()
      .one_of({"cel", "dem"});
  command
      .option("--case", args->case_file, "the hopper case whose outlet and semi-angle are varied")
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
              "points left out of the fit to test it (WIDTH@ANGLE,...; none)")
      .show_default()
      .type_name("LIST");
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
