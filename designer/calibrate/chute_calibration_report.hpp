#pragma once
// What a chute calibration found, in the three forms it leaves: the material's
// [calibration.chute] table, calibration.json, and the text a user reads (every inclination's
// reference and the chute check before and after; theta2 and L before and after).
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "designer/calibrate/calibration_report.hpp"
#include "designer/calibrate/chute_calibration_design.hpp"
#include "designer/calibrate/stop_law_fit.hpp"

namespace feedflow {

struct ChuteCalibrationOutcome {
  std::string material;  // its name
  ChuteCalibrationDesign design;
  std::vector<CalibrationPoint> points;       // one per design point, in the design's order
  std::vector<StopObservation> observations;  // the points with a usable reference ...
  std::vector<std::size_t> observed;          // ... and their places in `points`
  StopLawFit fit;
  std::size_t runs_made = 0, runs_read_back = 0;
  std::set<std::string> run_commits;
  std::string rung;  // the references' rung in words when read from verified designs (else empty)
};

// What the references were, in words: "L2 CEL-FEM, cells 20 and 10 mm (the levels that put 3
// cells across the deposit they find), Richardson".
std::string chute_rung_text(const ChuteCalibrationOutcome& outcome);

ChuteCalibration chute_calibration_table(const ChuteCalibrationOutcome& outcome,
                                         const std::string& scene, const std::string& commit,
                                         const std::string& date);
std::vector<ChutePointRecord> chute_point_records(const ChuteCalibrationOutcome& outcome);
nlohmann::ordered_json chute_calibration_json(const ChuteCalibrationOutcome& outcome,
                                              const ChuteCalibration& table);
std::string chute_calibration_summary(const ChuteCalibrationOutcome& outcome,
                                      const ChuteCalibration& table);

}  // namespace feedflow
