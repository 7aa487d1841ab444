#pragma once
// A material's TOML text as it was read: its file's, or the built-in one's; and that text
// without its [calibration] tables (what every solver reads of a material).
#include <string>
#include <string_view>

#include "models/material/material.hpp"

namespace feedflow {

// The text of the file the material came from, or of the built-in material; empty for a
// material defined inside a case file (the case's text holds it).
std::string material_text(const Material& material);

// The parts of a material's calibration, each written by its own `feedflow calibrate`: the
// hopper's discharge ([calibration], its discharge rows and points) and the drum's flowing layer
// ([calibration.drum] and its points), the arching models' strength ([calibration.arching]
// and its points), and the chute's stopping-thickness law ([calibration.chute] and its points).
enum class CalibrationPart { all, hopper, drum, arching, chute };

// `text` without the calibration tables of `part` ("[calibration]",
// "[calibration.discharge.beverloo]", "[[calibration.points]]"; "[calibration.drum]",
// "[[calibration.drum.points]]") and the comment lines just above them; no trailing blank lines.
std::string without_calibration(std::string_view text, CalibrationPart part = CalibrationPart::all);

}  // namespace feedflow
