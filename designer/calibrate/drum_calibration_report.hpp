#pragma once
// What a drum calibration found, in the three forms it leaves: the material's
// [calibration.drum] table, calibration.json, and the text a user reads (every speed's reference
// and the design check before and after; c_delta and the friction shift before and after).
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "designer/calibrate/calibration_report.hpp"
#include "designer/calibrate/drum_calibration_design.hpp"
#include "designer/calibrate/drum_layer_fit.hpp"

namespace feedflow {

struct DrumCalibrationOutcome {
  std::string material;  // its name
  DrumCalibrationDesign design;
  std::vector<CalibrationPoint> points;       // one per design point, in the design's order
  std::vector<DrumObservation> observations;  // the points with a usable reference ...
  std::vector<std::size_t> observed;          // ... and their places in `points`
  DrumLayerFit fit;
  std::size_t runs_made = 0, runs_read_back = 0;
  std::set<std::string> run_commits;
};

// What the references were, in words: "L2 CEL-FEM, cells 20, 10 and 5 mm (the bench's
// refinement series of the drum's radius), Richardson".
std::string drum_rung_text(const DrumCalibrationOutcome& outcome);

// `scene_drum`: the calibrated drum (its size and fill are recorded).
DrumCalibration drum_calibration_table(const DrumCalibrationOutcome& outcome,
                                       const std::string& scene, const Drum& scene_drum,
                                       const std::string& commit, const std::string& date);
std::vector<DrumPointRecord> drum_point_records(const DrumCalibrationOutcome& outcome);
nlohmann::ordered_json drum_calibration_json(const DrumCalibrationOutcome& outcome,
                                             const DrumCalibration& table);
std::string drum_calibration_summary(const DrumCalibrationOutcome& outcome,
                                     const DrumCalibration& table);

}  // namespace feedflow
