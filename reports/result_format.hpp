#pragma once
// How results read in every output (text, PDF, HTML): labels from quantity names, values with
// units, bands.
#include <string>

#include "models/core/estimate.hpp"

namespace feedflow {

// "critical_outlet_width" -> "critical outlet width"; "hopper.semi_angle" -> "semi angle".
std::string quantity_label(const std::string& name);
// "23.6 mm" or "mass"; numbers with 4 significant digits and the unit.
std::string estimate_value_text(const Estimate& e);
// "18 .. 31 mm", or "" without a band.
std::string estimate_band_text(const Estimate& e);

}  // namespace feedflow
