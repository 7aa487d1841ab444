#pragma once
// What a discharge calibration found, in the three forms it leaves: the material's
// [calibration] table, calibration.json, and the text a user reads (every point's reference and
// the design check before and after; every row's coefficients and errors before and after).
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "designer/bench/bench_table.hpp"
#include "designer/calibrate/calibration_design.hpp"
#include "designer/calibrate/calibration_toml.hpp"
#include "designer/calibrate/discharge_fit.hpp"

namespace feedflow {

// A design point's runs: its question, the reference they make, and "done" or why there is none.
struct CalibrationPoint {
  BenchQuestion question;
  BenchReference reference;
  std::string status = "done";
};

struct CalibrationOutcome {
  std::string material;                        // its name
  CalibrationDesign design;
  std::vector<CalibrationPoint> points;        // one per design point, in the design's order
  std::vector<DischargeObservation> observations;  // the points with a usable reference ...
  std::vector<std::size_t> observed;           // ... and their places in `points`
  DischargeFit fit;
  std::size_t runs_made = 0, runs_read_back = 0;
  std::set<std::string> run_commits;           // of the programs that made the runs ("" unrecorded)
};

// What the references were, in words: "L2 CEL-FEM, 3 and 6 cells across the half outlet,
// Richardson with order 0.763".
std::string rung_text(const CalibrationDesign& design);

// The material's table: the fitted rows with their figures; `commit` names the fitting program
// (and, where they differ, the runs' programs), `date` the day.
Calibration calibration_table(const CalibrationOutcome& outcome, const std::string& scene, bool wedge,
                              const std::string& density_model, const std::string& commit, const std::string& date);
std::vector<CalibrationPointRecord> calibration_point_records(const CalibrationOutcome& outcome);
// The program's commit, and the runs' where they differ.
std::string commit_text(const std::string& program, const std::set<std::string>& run_commits);

nlohmann::ordered_json calibration_json(const CalibrationOutcome& outcome, const Calibration& table);

// calibration.json's head, shared by every calibration: the material, the rung, the provenance
// and the runs made and read back.
nlohmann::ordered_json calibration_json_head(const std::string& material,
                                             const std::string& against, const std::string& rung,
                                             const std::string& commit, const std::string& date,
                                             std::size_t runs_made, std::size_t runs_read_back);
// One design point in calibration.json: its `setting` (the varied quantities with units), whether
// it was held out, its status and its reference.
nlohmann::ordered_json point_json(nlohmann::ordered_json setting, bool held_out,
                                  const CalibrationPoint& point);

std::string calibration_summary(const CalibrationOutcome& outcome, const Calibration& table);

}  // namespace feedflow
