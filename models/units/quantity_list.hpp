#pragma once
// A list of quantities typed on a command line: "40,70,100 mm" (one unit for the bare numbers),
// "40mm, 0.1 m", "15,27.5,40 deg". Each value in SI, checked against the expected dimension.
#include <string_view>
#include <vector>

#include "models/units/dimension.hpp"

namespace feedflow {

// Throws std::invalid_argument saying what is wrong (an empty item, a unit of another dimension,
// a bare number where no item carries a unit).
std::vector<double> parse_quantity_list(std::string_view text, const Dimension& expected);

}  // namespace feedflow
