#pragma once
// What an arching calibration found, in the three forms it leaves: the material's
// [calibration.arching] table, calibration.json, and the text a user reads (every semi-angle's
// bracket and each row's B_c before and after; each row's strength scale, the range every
// bracket allows, and its errors before and after).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "designer/calibrate/arching_records.hpp"
#include "designer/calibrate/calibration_toml.hpp"

namespace feedflow {

struct ArchingCalibrationOutcome {
  std::string material;
  std::string against;  // "dem" | "cel"
  std::string scene;    // the case's name
  std::string flow_factor;
  std::vector<ArchingRecord> records;
  std::vector<ArchingRowFit> fit;
};

// The material's table; `commit` names the fitting program and the runs' programs.
ArchingCalibration arching_calibration_table(const ArchingCalibrationOutcome& outcome,
                                             const std::string& commit, const std::string& date);
std::vector<ArchingPointRecord> arching_point_records(const ArchingCalibrationOutcome& outcome);
nlohmann::ordered_json arching_calibration_json(const ArchingCalibrationOutcome& outcome,
                                                const ArchingCalibration& table);
std::string arching_calibration_summary(const ArchingCalibrationOutcome& outcome,
                                        const ArchingCalibration& table);

}  // namespace feedflow
