#pragma once
// A material's [calibration] table as TOML text, and a material file's text with its
// calibration replaced (the rest of the file, comments and sources, kept as written).
#include <string>
#include <string_view>
#include <vector>

#include "designer/case/material_text.hpp"
#include "models/material/calibration.hpp"

namespace feedflow {

// One design point as the table records it (provenance: what the coefficients were fitted to).
struct CalibrationPointRecord {
  double outlet_width = 0.0;  // [m]
  double semi_angle = 0.0;    // [rad]
  double reference = 0.0;     // [kg/s]
  double error_bar = 0.0;     // [kg/s]
  bool held_out = false;
  std::string source;         // how the reference was made: "CEL two levels (10, 5 mm; ...)"
};

// One drum speed as [calibration.drum] records it.
struct DrumPointRecord {
  double speed = 0.0;      // [rad/s]
  double reference = 0.0;  // angle of repose [rad]
  double error_bar = 0.0;  // [rad]
  bool held_out = false;
  std::string source;
};

// One bracketed critical outlet width as [[calibration.arching.points]] records it.
struct ArchingPointRecord {
  double semi_angle = 0.0;           // [rad]
  double wall_friction_angle = 0.0;  // [rad]
  double arches_at = 0.0;            // [m] the widest outlet the rung saw arch
  double flows_at = 0.0;             // [m] the narrowest outlet the rung saw flow
  bool held_out = false;
  std::string source;  // the verified record it came from
};

// One inclination as [[calibration.chute.points]] records it.
struct ChutePointRecord {
  double angle = 0.0;      // [rad]
  double reference = 0.0;  // deposit thickness mid-ramp [m]
  double error_bar = 0.0;  // [m]
  bool held_out = false;
  std::string source;
};

// "[calibration.chute]" with its coefficients (theta2 in degrees, L in millimetres) and
// [[calibration.chute.points]].
std::string chute_calibration_toml(const ChuteCalibration& c,
                                   const std::vector<ChutePointRecord>& points);

// "[calibration.arching]" with its rows ([calibration.arching.rows.<row>]) and
// [[calibration.arching.points]].
std::string arching_calibration_toml(const ArchingCalibration& c,
                                     const std::vector<ArchingPointRecord>& points);

// "[calibration.drum]" with its coefficients (the friction shift in degrees) and
// [[calibration.drum.points]].
std::string drum_calibration_toml(const DrumCalibration& c,
                                  const std::vector<DrumPointRecord>& points);

// "[calibration]" with its discharge rows and [[calibration.points]]; coefficients in the
// shortest text that reads back as the same number.
std::string calibration_toml(const Calibration& c, const std::vector<CalibrationPointRecord>& points);

// `material_text` without the tables of its calibration's `part` (the other part is kept), with
// `table_text` appended after one blank line.
std::string with_calibration(std::string_view material_text, std::string_view table_text,
                             CalibrationPart part = CalibrationPart::hopper);

}  // namespace feedflow
