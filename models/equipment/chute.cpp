#include "models/equipment/chute.hpp"

#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

std::span<const FieldSpec<Chute>> chute_fields() {
  static const FieldSpec<Chute> fields[] = {
      number_field<Chute>("angle", &Chute::angle, dim::angle, "deg",
                          Range::open(0.0, 90.0 * kDegree), "ramp inclination from the horizontal"),
      number_field<Chute>("width", &Chute::width, dim::length, "mm", Range{0.0, 10.0, false, true},
                          "ramp width"),
      number_field<Chute>("length", &Chute::length, dim::length, "m", Range::closed(0.1, 10.0),
                          "ramp length along the slope (the L1 release runs on 10 mm cells; its work "
                          "grows with the ramp: 10 m takes seconds)"),
      number_field<Chute>("gate_opening", &Chute::gate_opening, dim::length, "mm",
                          Range::closed(0.01, 10.0),
                          "height of the gate opening above the ramp (the L1 release resolves it on "
                          "10 mm cells; below one cell it is not resolved and takes minutes)"),
      number_field<Chute>("bin_length", &Chute::bin_length, dim::length, "mm", Range::closed(0.05, 5.0),
                          "storage bin length in the flow direction (the L1 release's work grows with "
                          "it: 5 m takes seconds)"),
      number_field<Chute>("bin_height", &Chute::bin_height, dim::length, "mm", Range{0.0, 20.0, false, true},
                          "storage bin height"),
      number_field<Chute>("fill_height", &Chute::fill_height, dim::length, "m",
                          Range{0.0, 20.0, false, true}, "material height in the bin before the gate lifts"),
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
