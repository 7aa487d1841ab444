// feedflow calibrate MATERIAL --against cel|dem: fits the hopper discharge models' free
// coefficients to full-rung rates over a design of experiments (outlet width x semi-angle of a
// hopper case, some points held out), and writes them into the material file as [calibration].
// Runs are made through the bench's machinery and kept in the output folder: a repeated or
// interrupted calibration reads back what is done.
#include <chrono>
#include <ctime>
#include <fstream>
#include <sstream>
#include <iostream>
#include <memory>
#include <set>

#include "designer/bench/bench_run.hpp"
#include "designer/bench/bench_table.hpp"
#include "designer/calibrate/calibration_design.hpp"
#include "designer/calibrate/calibration_toml.hpp"
#include "designer/calibrate/discharge_fit.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/case/material_library.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/cli/output_folder.hpp"
#include "models/core/commit.hpp"
#include "models/core/errors.hpp"
#include "models/material/builtin_materials.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_list.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

struct CalibrateArguments {
  std::string material;
  std::string against;
  std::string case_file = "cases/pilot_hopper.toml";
  std::string outlet_widths = "40,70,100 mm";
  std::string semi_angles = "15,27.5,40 deg";
  std::string held_out = "45 mm@25 deg,75 mm@25 deg";
  std::vector<double> cells_across = {3.0, 6.0};
  std::optional<double> order;
  std::string time;
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

// What the references were, in words: "L2 CEL-FEM, 3 and 6 cells across the half outlet,
// Richardson with order 0.763".
std::string rung_text(const CalibrationDesign& d) {
  if (d.against == "dem") return "L3 DEM at the case's resolution";
  std::string levels;
  for (std::size_t k = 0; k < d.cells_across.size(); ++k)
    levels += (k == 0 ? "" : k + 1 == d.cells_across.size() ? " and " : ", ") + format_number(d.cells_across[k], 3);
  std::string s = "L2 CEL-FEM, " + levels + " cells across the half outlet";
  if (d.cells_across.size() == 2)
    s += ", Richardson with order " + format_number(d.order.value_or(measured_hopper_rate_order().order), 3);
  else if (d.cells_across.size() > 2)
    s += ", Richardson with the observed order";
  return s;
}

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The program's commit that fitted, and those that made the runs where they differ.
std::string commit_text(const std::set<std::string>& run_commits) {
  std::string text = kCommit;
  if (run_commits.size() == 1 && *run_commits.begin() == kCommit) return text;
  std::string runs;
  bool unrecorded = false;
  for (const auto& c : run_commits) {
    if (c.empty()) unrecorded = true;
    else runs += (runs.empty() ? "" : ", ") + c;
  }
  if (!runs.empty()) text += " (runs made by " + runs + (unrecorded ? " and earlier builds" : "") + ")";
  else if (unrecorded) text += " (runs made by an earlier build that did not record its commit)";
  return text;
}

std::string percent(double relative) { return format_number(100.0 * relative, 3) + " %"; }

struct PointOutcome {
  BenchQuestion question;
  BenchReference reference;
  std::string status = "done";  // or why there is no reference
};

// Each point's runs, made or read back; stops at Ctrl-C.
bool make_runs(const CalibrateArguments& args, const std::filesystem::path& runs_root, std::vector<PointOutcome>& points,
               std::size_t& made, std::size_t& read_back, std::set<std::string>& commits) {
  const bool say = args.options.human_output();
  std::size_t total = 0, k = 0;
  for (const auto& p : points) total += p.question.points.size();
  for (auto& outcome : points) {
    std::map<std::string, BenchRun> runs;
    for (const auto& bp : outcome.question.points) {
      ++k;
      const auto folder = bench_run_folder(runs_root, outcome.question, bp);
      if (say && !saved_bench_run(folder, bench_invocation(outcome.question, bp)))
        std::cout << "[" << k << "/" << total << "] " << outcome.question.title << ": " << bp.setting << " ..." << std::flush;
      bool was_made = false;
      BenchRun run = run_or_read_back(outcome.question, bp, ".", folder, was_made);
      if (was_made) {
        ++made;
        if (say) std::cout << " " << format_number(run.wall_seconds, 3) << " s" << (run.done() ? "" : " (" + run.status + ")") << '\n';
        if (run.status == "interrupted" || interrupt_requested()) return false;
      } else {
        ++read_back;
      }
      if (!run.done()) outcome.status = run.status;
      commits.insert(run.commit);
      runs[point_id(bp)] = std::move(run);
    }
    outcome.reference = tabulate(outcome.question, runs).reference;
    const BenchReference& r = outcome.reference;
    if (outcome.status != "done") continue;
    if (!r.value || !(*r.value > 0.0)) outcome.status = "no reference rate";
    else if (r.error_bar && *r.error_bar > kUsableUncertainty * *r.value)
      outcome.status = "reference too uncertain (" + format_number(*r.value, 3) + " +- " + format_number(*r.error_bar, 2) +
                       " kg/s)";
  }
  return true;
}

nlohmann::ordered_json coefficients_json(const DischargeModel& row, const std::vector<double>& c) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < row.coefficients.size(); ++i) j[std::string(row.coefficients[i].name)] = c[i];
  return j;
}

int run_calibrate(const CalibrateArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  const CalibrationDesign design = design_of(args);
  const Material material = MaterialLibrary::standard(std::filesystem::path(args.case_file).parent_path()).load(args.material);
  std::vector<PointOutcome> points;
  for (const auto& p : design.points) points.push_back({design_point_question(design, p), {}, "done"});
  if (args.list) {
    for (const auto& p : points)
      for (const auto& bp : p.question.points) std::cout << bench_invocation(p.question, bp) << '\n';
    return kExitOk;
  }
  // Every point's case must load (a typo in --case, a width the case refuses) before hours of runs.
  std::vector<Case> cases;
  for (const auto& p : points) {
    std::vector<SetOverride> overrides;
    for (const auto& s : p.question.sets) overrides.push_back(parse_set_override(s));
    cases.push_back(load_case(design.case_file, overrides));
    if (!std::holds_alternative<Hopper>(cases.back().equipment))
      throw InputError("--case", design.case_file, "a discharge calibration needs a hopper case");
  }
  const std::filesystem::path out =
      args.options.out.empty() ? std::filesystem::path("out/calibrate") / file_name_friendly(material.name)
                               : std::filesystem::path(args.options.out);
  OutputFolder folder(out, "--out");
  install_interrupt_handler();
  std::size_t made = 0, read_back = 0;
  std::set<std::string> runs_commits;
  const bool finished = make_runs(args, out / "runs", points, made, read_back, runs_commits);
  if (!finished) {
    std::cerr << "feedflow: interrupted; run the same command again to continue (runs made are kept)\n";
    return kExitInterrupted;
  }

  std::vector<DischargeObservation> observations;
  std::vector<const PointOutcome*> used;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].status != "done") continue;
    observations.push_back({std::get<Hopper>(cases[i].equipment), *points[i].reference.value, points[i].reference.error_bar.value_or(0.0),
                            design.points[i].held_out});
    used.push_back(&points[i]);
  }
  const std::size_t fitted = std::count_if(observations.begin(), observations.end(),
                                           [](const DischargeObservation& o) { return !o.held_out; });
  if (fitted < 2)
    throw NumericalFailure("calibration: only " + std::to_string(fitted) +
                           " fitted point(s) have a reference rate; see the runs in " + (out / "runs").string());
  const HopperDensityModel& density = hopper_density_models().default_row();
  const DischargeFit fit = fit_discharge(observations, HopperMaterial::of(material, density));

  Calibration c;
  c.against = design.against;
  c.rung = rung_text(design);
  c.scene = cases.front().name;
  c.geometry = std::get<Hopper>(cases.front().equipment).is_wedge() ? "wedge" : "conical";
  c.density_model = std::string(density.name);
  c.commit = commit_text(runs_commits);
  c.date = today();
  c.points = observations.size();
  for (const auto& row : fit.rows) {
    if (!row.failure.empty()) continue;
    CalibratedModel m;
    for (std::size_t i = 0; i < row.after.size(); ++i) m.coefficients[std::string(row.row->coefficients[i].name)] = row.after[i];
    m.figures["fit_rms_error_before"] = percent(row.fit_rms_before);
    m.figures["fit_rms_error"] = percent(row.fit_rms_after);
    if (fitted < observations.size()) {
      m.figures["held_out_max_error_before"] = percent(row.held_out_max_before);
      m.figures["held_out_max_error"] = percent(row.held_out_max_after);
    }
    for (std::size_t k = 0; k < row.held.size(); ++k) m.figures["held_" + std::to_string(k + 1)] = row.held[k];
    c.discharge[std::string(row.row->name)] = std::move(m);
  }
  std::vector<CalibrationPointRecord> records;
  for (std::size_t i = 0; i < observations.size(); ++i)
    records.push_back({observations[i].hopper.outlet_width, observations[i].hopper.semi_angle, observations[i].reference,
                       observations[i].error_bar, observations[i].held_out, used[i]->reference.source});

  // The material file: the one it came from, or a copy beside the runs for a built-in material.
  const std::filesystem::path target = !args.write.empty()            ? std::filesystem::path(args.write)
                                       : material.origin != "built-in" ? std::filesystem::path(material.origin)
                                                                       : out / (file_name_friendly(material.name) + ".toml");
  std::string material_text;
  if (std::filesystem::exists(material.origin)) material_text = file_text(material.origin);
  else
    for (const auto& b : builtin_material_texts())
      if (b.name == material.name) material_text = std::string(b.toml);
  const std::string calibrated_text = with_calibration(material_text, calibration_toml(c, records));

  nlohmann::ordered_json j;
  j["feedflow_calibrate"] = material.name;
  j["command_line"] = invocation();
  j["against"] = c.against;
  j["rung"] = c.rung;
  j["commit"] = c.commit;
  j["date"] = c.date;
  j["runs_made"] = made;
  j["runs_read_back"] = read_back;
  auto& jp = j["points"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& d = design.points[i];
    nlohmann::ordered_json p{{"outlet_width", {{"value", d.outlet_width}, {"unit", "m"}}},
                             {"semi_angle", {{"value", d.semi_angle}, {"unit", "rad"}}},
                             {"held_out", d.held_out},
                             {"status", points[i].status}};
    if (points[i].reference.value)
      p["reference"] = {{"value", *points[i].reference.value},
                        {"error_bar", points[i].reference.error_bar.value_or(0.0)},
                        {"unit", "kg/s"},
                        {"source", points[i].reference.source}};
    jp.push_back(p);
  }
  auto& jr = j["models"] = nlohmann::ordered_json::array();
  for (const auto& row : fit.rows)
    jr.push_back({{"model", row.row->name},
                  {"before", coefficients_json(*row.row, row.before)},
                  {"after", coefficients_json(*row.row, row.after)},
                  {"standard_errors", coefficients_json(*row.row, row.standard_errors)},
                  {"fit_rms_error_before", row.fit_rms_before},
                  {"fit_rms_error_after", row.fit_rms_after},
                  {"held_out_max_error_before", row.held_out_max_before},
                  {"held_out_max_error_after", row.held_out_max_after},
                  {"rate_before", row.rate_before},
                  {"rate_after", row.rate_after},
                  {"held", row.held},
                  {"failure", row.failure}});
  j["design_check"] = {{"rate_before", fit.design_before},
                       {"rate_after", fit.design_after},
                       {"band_holds_reference_before", fit.band_holds_before},
                       {"band_holds_reference_after", fit.band_holds_after}};
  j["material_file"] = target.string();
  j["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string json_text = j.dump(2) + "\n";
  std::vector<OutputFile> files = {{out / "calibration.json", json_text, "--out"}, {target, calibrated_text, "--write"}};
  if (!args.options.json.empty() && !args.options.json_to_stdout()) files.push_back({args.options.json, json_text, "--json"});
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json_text : nullptr, args.options.verbose, &folder);

  if (args.options.human_output()) {
    std::cout << "Discharge rate, " << material.name << ", against " << c.rung << " (" << observations.size()
              << " points, " << observations.size() - fitted << " held out):\n";
    for (std::size_t i = 0; i < observations.size(); ++i)
      std::cout << "  W = " << format_number(observations[i].hopper.outlet_width * 1e3, 4) << " mm, theta = "
                << format_number(in_degrees(observations[i].hopper.semi_angle), 4) << " deg"
                << (observations[i].held_out ? " (held out)" : "") << ": reference "
                << format_number(observations[i].reference, 4) << " +- " << format_number(observations[i].error_bar, 2)
                << " kg/s; design check " << format_number(fit.design_before[i], 4) << " -> "
                << format_number(fit.design_after[i], 4) << " kg/s, band holds it: "
                << (fit.band_holds_before[i] ? "yes" : "no") << " -> " << (fit.band_holds_after[i] ? "yes" : "no") << '\n';
    for (const auto& row : fit.rows) {
      std::cout << "  " << row.row->name << ": " << coefficients_text(*row.row, row.before) << " -> "
                << coefficients_text(*row.row, row.after) << "; rms error " << percent(row.fit_rms_before) << " -> "
                << percent(row.fit_rms_after);
      if (fitted < observations.size())
        std::cout << ", held-out max " << percent(row.held_out_max_before) << " -> " << percent(row.held_out_max_after);
      for (const auto& h : row.held) std::cout << " (" << h << ")";
      if (!row.failure.empty()) std::cout << " (not fitted: " << row.failure << ")";
      std::cout << '\n';
    }
    for (std::size_t i = 0; i < points.size(); ++i)
      if (points[i].status != "done")
        std::cout << "  " << points[i].question.title << ": left out, " << points[i].status << '\n';
    std::cout << made << " run(s) made, " << read_back << " read back\nWritten: ";
    for (std::size_t i = 0; i < written.size(); ++i) std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
  return kExitOk;
}

}  // namespace

void add_calibrate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CalibrateArguments>();
  auto* command = app.add_subcommand(
      "calibrate", "fit the reduced models' discharge coefficients to a full rung over a design of experiments");
  command->add_option("material", args->material, "the material to calibrate (see `feedflow materials`)")->required();
  command->add_option("--against", args->against, "the full rung to fit to")
      ->required()
      ->check(CLI::IsMember({"cel", "dem"}));
  command->add_option("--case", args->case_file, "the hopper case whose outlet and semi-angle are varied")
      ->capture_default_str()
      ->type_name("FILE");
  command->add_option("--outlet-widths", args->outlet_widths, "outlet widths of the fitted grid")
      ->capture_default_str()
      ->type_name("LIST");
  command->add_option("--semi-angles", args->semi_angles, "semi-angles of the fitted grid")
      ->capture_default_str()
      ->type_name("LIST");
  command->add_option("--held-out", args->held_out, "points left out of the fit to test it (WIDTH@ANGLE,...; none)")
      ->capture_default_str()
      ->type_name("LIST");
  command->add_option("--cells-across", args->cells_across,
                      "CEL levels: cells across the half outlet, each twice the last (Richardson)")
      ->delimiter(',')
      ->capture_default_str()
      ->type_name("N[,N...]");
  command->add_option("--order", args->order,
                      "order two CEL levels extrapolate with (default: the order in the shipped bench table)");
  command->add_option("--time", args->time, "simulated time of each run (default: the scene's own)")->type_name("TIME");
  command->add_option("--write", args->write,
                      "material file to write (default: the material's own file; a built-in material: "
                      "OUT/<name>.toml)")
      ->type_name("FILE");
  command->add_flag("--list", args->list, "list the runs the calibration makes, then stop");
  command->add_option("--out", args->options.out,
                      "output folder (default out/calibrate/<material>); runs already in it are read back")
      ->type_name("DIR");
  add_json_option(*command, args->options, "the calibration JSON");
  add_verbosity_options(*command, args->options, true);
  command->callback([args, &exit_code] { exit_code = run_calibrate(*args); });
}

}  // namespace feedflow
