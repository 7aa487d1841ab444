#include "models/equipment/drum.hpp"

#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

std::span<const FieldSpec<Drum>> drum_fields() {
  static const FieldSpec<Drum> fields[] = {
      number_field<Drum>("diameter", &Drum::diameter, dim::length, "mm", Range::closed(0.01, 10.0),
                         "internal drum diameter"),
      number_field<Drum>("length", &Drum::length, dim::length, "mm", Range::closed(0.01, 100.0),
                         "internal drum length between the end walls"),
      number_field<Drum>("fill_fraction", &Drum::fill_fraction, dim::dimensionless, "%",
                         Range::open(0.0, 1.0), "filled fraction of the drum cross-section"),
      number_field<Drum>("speed", &Drum::speed, dim::angular_speed, "rpm",
                         Range{0.0, 1000.0 * 2.0 * std::numbers::pi / 60.0, false, true},
                         "rotation speed"),
      optional_number_field<Drum>("wall_friction_angle", &Drum::wall_friction_angle, dim::angle,
                                  "deg", Range::half_open(0.0, 90.0 * kDegree),
                                  "wall friction angle of the material on the drum shell"),
  };
  return fields;
}

std::vector<FieldProblem> check(const Drum& d) {
  std::vector<FieldProblem> problems;
  if (d.length < d.diameter / 4.0)
    problems.push_back({"length",
                        "is under a quarter of the diameter (" +
                            format_quantity(d.diameter / 4.0, "mm") +
                            "): end-wall friction dominates and slice models err low",
                        false});
  return problems;
}

}  // namespace feedflow
