#include "designer/cli/calibration_runs.hpp"

#include <ctime>

#include "designer/bench/bench_table.hpp"
#include "designer/calibrate/discharge_fit.hpp"
#include "designer/case/material_library.hpp"
#include "designer/cli/invocation.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/verify/verified_bench_point.hpp"
#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_list.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow::calibrate_cli {

std::vector<double> quantity_list(const std::string& text, const Dimension& d, const char* flag) {
  try {
    return parse_quantity_list(text, d);
  } catch (const std::invalid_argument& e) {
    throw InputError(flag, text, e.what());
  }
}

// The material being calibrated, from the case's folder's library.
Material calibrated_material(const CalibrateArguments& args) {
  return MaterialLibrary::standard(std::filesystem::path(args.case_file).parent_path())
      .load(args.material);
}

// --held-out as a list of `d` (empty: `fallback`; "none": nothing).
std::vector<double> held_out_list(const CalibrateArguments& args, const Dimension& d,
                                  const char* fallback) {
  const std::string text = args.held_out.empty() ? fallback : args.held_out;
  if (text.empty() || text == "none") return {};
  return quantity_list(text, d, "--held-out");
}

// --list: every point's run as a command line.
void list_runs(const std::vector<CalibrationPoint>& points) {
  for (const auto& p : points)
    for (const auto& bp : p.question.points) std::cout << bench_invocation(p.question, bp) << '\n';
}

// Throws NumericalFailure unless at least two fitted points (`what`: "point(s) have a reference
// rate") have a reference.
void require_two_fitted(std::ptrdiff_t fitted, const std::string& what,
                        const std::filesystem::path& out) {
  if (fitted < 2)
    throw NumericalFailure("calibration: only " + std::to_string(fitted) + " fitted " + what +
                           "; see the runs in " + (out / "runs").string());
}

double finest_cell(const CalibrateArguments& args, const char* scene_default) {
  const std::string text = args.finest_cell.empty() ? scene_default : args.finest_cell;
  try {
    return parse_quantity_as(text, dim::length, false);
  } catch (const std::invalid_argument& e) {
    throw InputError("--finest-cell", text, e.what());
  }
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", std::gmtime(&now));
  return text;
}

// Each point's runs, made or read back, and its reference; false when Ctrl-C stopped them.
bool make_runs(const CalibrateArguments& args, const std::filesystem::path& runs_root,
               std::vector<CalibrationPoint>& points, RunTally& tally, const LevelCheck& check) {
  const bool say = args.options.human_output();
  std::size_t total = 0, k = 0;
  for (const auto& p : points) total += p.question.points.size();
  for (auto& point : points) {
    std::map<std::string, BenchRun> runs;
    for (const auto& bp : point.question.points) {
      ++k;
      const auto folder = bench_run_folder(runs_root, point.question, bp);
      const bool announced = say && !saved_run_of(point.question, bp, ".", folder);
      if (announced)
        std::cout << "[" << k << "/" << total << "] " << point.question.title << ": " << bp.setting
                  << " ..." << std::flush;
      bool was_made = false;
      BenchRun run = run_or_read_back_any(point.question, bp, ".", folder, was_made);
      if (announced)
        std::cout << " " << (was_made ? format_number(run.wall_seconds, 3) + " s" : "read back")
                  << (run.done() ? "" : " (" + run.status + ")") << '\n';
      if (was_made) {
        ++tally.made;
        if (run.status == "interrupted" || interrupt_requested()) return false;
      } else {
        ++tally.read_back;
      }
      if (!run.done()) point.status = run.status;
      tally.commits.insert(run.commit);
      runs[point_id(bp)] = std::move(run);
    }
    if (check && point.status == "done")
      if (std::string why = check(point.question, runs); !why.empty())
        point.status = std::move(why);
    point.reference = tabulate(point.question, runs).reference;
    const BenchReference& r = point.reference;
    if (point.status != "done") continue;
    if (!r.value || !(*r.value > 0.0))
      point.status = "no reference value";
    else if (r.error_bar && *r.error_bar > kUsableUncertainty * *r.value)
      point.status = "reference too uncertain (" + format_number(*r.value, 3) + " +- " +
                     format_number(*r.error_bar, 2) + " " + r.unit + ")";
  }
  return true;
}

// The output folder: --out, or out/calibrate/<material>.
std::filesystem::path output_folder(const CalibrateArguments& args, const Material& material) {
  return args.options.out.empty()
             ? std::filesystem::path("out/calibrate") / file_name_friendly(material.name)
             : std::filesystem::path(args.options.out);
}

// The material file: --write, the one the material came from, or a copy beside the runs for a
// built-in material.
std::filesystem::path material_target(const CalibrateArguments& args, const Material& material,
                                      const std::filesystem::path& out) {
  if (!args.write.empty()) return args.write;
  if (material.origin != "built-in") return material.origin;
  return out / (file_name_friendly(material.name) + ".toml");
}

// calibration.json (with the command and the wall time), the material file and --json; then
// the summary and what was written.
void write_calibration(const CalibrateArguments& args, nlohmann::ordered_json j,
                       const std::filesystem::path& out, const std::filesystem::path& target,
                       const std::string& material_file_text, OutputFolder& folder,
                       const std::string& summary, std::chrono::steady_clock::time_point start) {
  j["command_line"] = invocation();
  j["material_file"] = target.string();
  j["wall_seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string json_text = j.dump(2) + "\n";
  std::vector<OutputFile> files = {{out / "calibration.json", json_text, "--out"},
                                   {target, material_file_text, "--write"}};
  if (!args.options.json.empty() && !args.options.json_to_stdout())
    files.push_back({args.options.json, json_text, "--json"});
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json_text : nullptr,
                                     args.options.verbose, &folder);
  if (args.options.human_output()) {
    std::cout << summary << "Written: ";
    for (std::size_t i = 0; i < written.size(); ++i)
      std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
}

std::string runs_text(std::size_t made, std::size_t read_back) {
  return std::to_string(made) + " run(s) made, " + std::to_string(read_back) + " read back\n";
}

}  // namespace feedflow::calibrate_cli
