#pragma once
// Formatting SI values for people: always with a unit ("60 mm", "30 deg", "2.09 rad/s").
#include <string>
#include <string_view>

namespace feedflow {

// The SI value converted to `unit` and printed with `significant` digits, then the unit:
// format_quantity(0.06, "mm") == "60 mm". An empty unit or "-" prints the bare number.
std::string format_quantity(double si, std::string_view unit, int significant = 4);

// The number alone, in `unit`, with `significant` digits and no trailing zeros.
std::string format_number(double value, int significant = 4);

// SI value expressed in `unit` (0.06 m in "mm" is 60).
double convert_to(double si, std::string_view unit);

}  // namespace feedflow
