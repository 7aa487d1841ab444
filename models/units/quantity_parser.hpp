#pragma once
// Parsing of quantities written with units: "60 mm", "30 deg", "20 rpm", "290 kg/m^3",
// "187.6 kPa", "1 us", "50 %", "9.81 m/s^2". Results are SI (angles in radians).
#include <stdexcept>
#include <string>
#include <string_view>

#include "models/units/dimension.hpp"

namespace feedflow {

// Thrown for text that is not a quantity, or a quantity of the wrong dimension. The message says
// what was expected; callers add the file, line and key.
class UnitError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct Quantity {
  double si = 0.0;       // value in SI units (radians for angles)
  Dimension dimension;   // its dimension
};

// A unit expression alone ("mm", "kg/m^3", "rev/min"): its SI factor and dimension.
Quantity parse_unit(std::string_view unit);

// A number followed by an optional unit ("60 mm", "32deg", "0.5"). No unit means dimensionless.
Quantity parse_quantity(std::string_view text);

// Parses text and checks its dimension. A bare number (no unit) is accepted for any dimension
// and taken as SI, as in case files; `bare_number_is_si = false` rejects it for dimensioned
// quantities.
double parse_quantity_as(std::string_view text, const Dimension& expected,
                         bool bare_number_is_si = true);

}  // namespace feedflow
