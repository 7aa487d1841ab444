#pragma once
// What every `feedflow calibrate` shares: its arguments, the design points' runs made or read back
// through the bench's machinery (kept in OUT/runs), and the calibration written out
// (calibration.json, the material file, --json, the summary).
#include <chrono>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "designer/bench/bench_run.hpp"
#include "designer/calibrate/calibration_report.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/output_folder.hpp"
#include "models/material/material.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/dimension.hpp"

namespace feedflow::calibrate_cli {

struct CalibrateArguments {
  std::string material;
  std::string against;
  std::string case_file = "cases/pilot_hopper.toml";
  // The design measured on the pilot hopper: 12 CEL runs, about 40 min on 2 cores (W 40 mm at
  // 15 deg alone would take about 30 min at 6 cells across the half outlet).
  std::string outlet_widths = "50,100 mm";
  std::string semi_angles = "20,35 deg";
  std::string held_out;  // empty: the scene's default
  // A drum: its speeds, all within the material's rolling regime (the angle model's domain). The
  // CEL drum's runs at 10 and 20 rpm are the bench's (read back when its run folders are here).
  std::string speeds = "10,20,30 rpm";
  // An inclined plane: its fitted inclinations (the seed's two).
  std::string angles = "29.5,37 deg";
  std::string finest_cell;  // empty: a drum's 5 mm, a plane's 10 mm
  std::vector<double> cells_across = {3.0, 6.0};
  std::optional<double> order;
  std::string time = "1s";  // after the opening, as the bench measured the hopper's rate
  // Verified design records (results.json) whose critical outlet widths an arching calibration
  // fits.
  std::vector<std::string> arching;
  // Verified chute design records (results.json) whose h_stop brackets a chute calibration fits.
  std::vector<std::string> stopping;
  std::string write;
  bool list = false;
  CommandOptions options;
};

constexpr const char* kHopperHeldOut = "60 mm@30 deg,75 mm@25 deg";
constexpr const char* kDrumHeldOut = "15,25 rpm";

struct RunTally {
  std::size_t made = 0, read_back = 0;
  std::set<std::string> commits;  // of the programs that made the runs ("" unrecorded)
};

// A check of a point's runs before its reference is made (it may take levels out of the
// reference): why the point has no reference, or empty.
using LevelCheck =
    std::function<std::string(BenchQuestion&, const std::map<std::string, BenchRun>&)>;

// `text` as a list of quantities of `d`; InputError naming `flag` otherwise.
std::vector<double> quantity_list(const std::string& text, const Dimension& d, const char* flag);

// The material being calibrated, from the case's folder's library.
Material calibrated_material(const CalibrateArguments& args);

// --held-out as a list of `d` (empty: `fallback`; "none": nothing).
std::vector<double> held_out_list(const CalibrateArguments& args, const Dimension& d,
                                  const char* fallback = "");

// --list: every point's run as a command line.
void list_runs(const std::vector<CalibrationPoint>& points);

// Throws NumericalFailure unless at least two fitted points (`what`: "point(s) have a reference
// rate") have a reference.
void require_two_fitted(std::ptrdiff_t fitted, const std::string& what,
                        const std::filesystem::path& out);

// --finest-cell, or the scene's default ("5mm").
double finest_cell(const CalibrateArguments& args, const char* scene_default);

// "2026-12-07" (UTC): the calibration's date.
std::string today();

// Each point's runs, made or read back, and its reference; false when Ctrl-C stopped them.
bool make_runs(const CalibrateArguments& args, const std::filesystem::path& runs_root,
               std::vector<CalibrationPoint>& points, RunTally& tally, const LevelCheck& check);

// The output folder: --out, or out/calibrate/<material>.
std::filesystem::path output_folder(const CalibrateArguments& args, const Material& material);

// The material file: --write, the one the material came from, or a copy beside the runs for a
// built-in material.
std::filesystem::path material_target(const CalibrateArguments& args, const Material& material,
                                      const std::filesystem::path& out);

// calibration.json (with the command and the wall time), the material file and --json; then
// the summary and what was written.
void write_calibration(const CalibrateArguments& args, nlohmann::ordered_json j,
                       const std::filesystem::path& out, const std::filesystem::path& target,
                       const std::string& material_file_text, OutputFolder& folder,
                       const std::string& summary, std::chrono::steady_clock::time_point start);

// "2 run(s) made, 6 read back" and a newline.
std::string runs_text(std::size_t made, std::size_t read_back);

// Every point's runs made or read back below OUT/runs, the tally in the outcome; false (having
// said how to continue) when Ctrl-C stopped them.
template <class Outcome>
bool run_points(const CalibrateArguments& args, const std::filesystem::path& out, Outcome& o,
                const LevelCheck& check = {}) {
  install_interrupt_handler();
  RunTally tally;
  const bool complete = make_runs(args, out / "runs", o.points, tally, check);
  o.runs_made = tally.made;
  o.runs_read_back = tally.read_back;
  o.run_commits = tally.commits;
  if (!complete) std::cerr << continue_after_interrupt(out / "runs");
  return complete;
}

}  // namespace feedflow::calibrate_cli
