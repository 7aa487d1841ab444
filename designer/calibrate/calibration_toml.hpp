#pragma once
// A material's [calibration] table as TOML text, and a material file's text with its
// calibration replaced (the rest of the file, comments and sources, kept as written).
#include <string>
#include <string_view>
#include <vector>

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

// "[calibration]" with its discharge rows and [[calibration.points]]; coefficients in the
// shortest text that reads back as the same number.
std::string calibration_toml(const Calibration& c, const std::vector<CalibrationPointRecord>& points);

// `material_text` without its [calibration] tables (every table whose header starts with
// "calibration"), with `table_text` appended after one blank line.
std::string with_calibration(std::string_view material_text, std::string_view table_text);

}  // namespace feedflow
