#include "models/equipment/chute.hpp"

#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

std::span<const FieldSpec<Chute>> chute_fields() {
  static const FieldSpec<Chute> fields[] = {
      number_field<Chute>("angle", &Chute::angle, dim::angle, "deg",
                          Range::open(0.0, 90.0 * kDegree), "ramp inclination from the horizontal"),
      number_field<Chute>("width", &Chute::width, dim::length, "mm", Range::positive(),
                          "ramp width"),
      number_field<Chute>("length", &Chute::length, dim::length, "m", Range::positive(),
                          "ramp length along the slope"),
      number_field<Chute>("gate_opening", &Chute::gate_opening, dim::length, "mm",
                          Range::positive(), "height of the gate opening above the ramp"),
      number_field<Chute>("bin_length", &Chute::bin_length, dim::length, "mm", Range::positive(),
                          "storage bin length in the flow direction"),
      number_field<Chute>("bin_height", &Chute::bin_height, dim::length, "mm", Range::positive(),
                          "storage bin height"),
      number_field<Chute>("fill_height", &Chute::fill_height, dim::length, "m",
                          Range::positive(), "material height in the bin before the gate lifts"),
  };
  return fields;
}

std::vector<FieldProblem> check(const Chute& c) {
  std::vector<FieldProblem> problems;
  if (c.fill_height > c.bin_height)
    problems.push_back({"fill_height", "must not exceed bin_height (" +
                                           format_quantity(c.bin_height, "mm") + "), got " +
                                           format_quantity(c.fill_height, "mm")});
  if (c.gate_opening > c.bin_height)
    problems.push_back({"gate_opening", "must not exceed bin_height (" +
                                            format_quantity(c.bin_height, "mm") + "), got " +
                                            format_quantity(c.gate_opening, "mm")});
  return problems;
}

}  // namespace feedflow
