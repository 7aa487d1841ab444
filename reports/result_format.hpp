#pragma once
// How results read in every output (text, PDF, HTML): labels from quantity names, values with
// units, bands.
#include <string>

#include "models/core/estimate.hpp"

namespace feedflow {

// The result key of the reduced-model value of `name` shown beside a simulated one:
// "mass_flow_rate" -> "mass_flow_rate_reduced_model" (one naming for every scene and rung).
std::string reduced_model_key(const std::string& name);

// "critical_outlet_width" -> "critical outlet width"; "hopper.semi_angle" -> "semi angle";
// "mass_flow_rate_reduced_model" -> "mass flow rate (reduced model)".
std::string quantity_label(const std::string& name);
// "23.6 mm" or "mass"; numbers with 4 significant digits and the unit.
std::string estimate_value_text(const Estimate& e);
// "18 .. 31 mm", or "" without a band.
std::string estimate_band_text(const Estimate& e);

}  // namespace feedflow
