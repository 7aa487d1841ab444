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

// `text` without the tables whose header starts with "calibration" ("[calibration]",
// "[calibration.discharge.beverloo]", "[[calibration.points]]") and the comment lines just above
// them; no trailing blank lines.
std::string without_calibration(std::string_view text);

}  // namespace feedflow
