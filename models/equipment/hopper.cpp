#include "models/equipment/hopper.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {
constexpr std::string_view kShapes[] = {"wedge", "conical"};
// Walls flatter than this from the vertical make a flat-bottomed bin: the radial stress field
// and Johanson's discharge model are for converging hoppers.
constexpr double kMaxSemiAngle = 80.0 * kDegree;
}  // namespace

double Hopper::outlet_height() const { return 0.5 * outlet_width / std::tan(semi_angle); }
double Hopper::transition_height() const { return 0.5 * bin_width / std::tan(semi_angle); }

double Hopper::filled_volume() const {
  const double t = std::tan(semi_angle);
  const double h0 = outlet_height(), ht = transition_height();
  const double top_of_cone = std::clamp(fill_height, h0, ht);
  const double bin_part = std::max(0.0, fill_height - ht);
  if (is_wedge()) {
    // Cross-section 2 h tan(theta) wide at height h, then the bin's full width.
    const double area = t * (top_of_cone * top_of_cone - h0 * h0) + bin_width * bin_part;
    return area * slot_length.value_or(0.0);
  }
  // Frustum between the outlet and the transition, then the cylinder.
  const double cone = std::numbers::pi / 3.0 * t * t * (std::pow(top_of_cone, 3) - std::pow(h0, 3));
  return cone + std::numbers::pi / 4.0 * bin_width * bin_width * bin_part;
}

std::span<const FieldSpec<Hopper>> hopper_fields() {
  static const FieldSpec<Hopper> fields[] = {
      label_field<Hopper>("shape", &Hopper::shape, kShapes,
                          "wedge (plane flow, slot outlet) or conical (circular outlet)"),
      number_field<Hopper>("semi_angle", &Hopper::semi_angle, dim::angle, "deg",
                           Range{0.0, kMaxSemiAngle, false, true},
                           "hopper wall angle measured from the vertical (a flatter wall makes a "
                           "flat-bottomed bin, outside the converging-hopper models)"),
      number_field<Hopper>("outlet_width", &Hopper::outlet_width, dim::length, "mm",
                           Range{0.0, 10.0, false, true}, "slot width (wedge) or outlet diameter (conical)"),
      number_field<Hopper>("fill_height", &Hopper::fill_height, dim::length, "m",
                           Range{0.0, 100.0, false, true},
                           "height of the material top above the virtual apex of the hopper"),
      number_field<Hopper>("bin_width", &Hopper::bin_width, dim::length, "m", Range{0.0, 50.0, false, true},
                           "width (wedge) or diameter (conical) of the vertical bin section"),
      optional_number_field<Hopper>("slot_length", &Hopper::slot_length, dim::length, "m",
                                    Range{0.0, 50.0, false, true},
                                    "out-of-plane length of a wedge hopper's slot outlet"),
      optional_number_field<Hopper>("wall_friction_angle", &Hopper::wall_friction_angle,
                                    dim::angle, "deg", Range::half_open(0.0, 90.0 * kDegree),
                                    "wall friction angle of the material on the hopper wall "
                                    "(defaults to the material's)"),
  };
  return fields;
}

std::vector<FieldProblem> check(const Hopper& h) {
  std::vector<FieldProblem> problems;
  if (h.outlet_width >= h.bin_width)
    problems.push_back({"outlet_width",
                        "must be smaller than bin_width (" + format_quantity(h.bin_width, "mm") +
                            "), got " + format_quantity(h.outlet_width, "mm")});
  if (h.fill_height <= h.outlet_height())
    problems.push_back({"fill_height",
                        "must be above the outlet, which sits " +
                            format_quantity(h.outlet_height(), "m") +
                            " above the virtual apex; got " + format_quantity(h.fill_height, "m")});
  if (h.is_wedge()) {
    if (!h.slot_length)
      problems.push_back({"slot_length", "is required for a wedge hopper (out-of-plane length "
                                         "of the slot outlet, e.g. \"0.5 m\")"});
    else if (*h.slot_length < h.outlet_width)
      problems.push_back({"slot_length", "must be at least the outlet width (" + format_quantity(h.outlet_width, "mm") +
                                             ") for a slot outlet, got " + format_quantity(*h.slot_length, "mm") +
                                             " (a slot shorter than it is wide is no plane-flow wedge)"});
    else if (*h.slot_length < 3.0 * h.outlet_width)
      problems.push_back({"slot_length",
                          "is shorter than 3 outlet widths (" +
                              format_quantity(3.0 * h.outlet_width, "mm") +
                              "): end walls disturb plane flow, so plane-flow results err "
                              "on the unsafe side",
                          false});
  } else if (h.slot_length) {
    problems.push_back({"slot_length", "applies to wedge hoppers only; remove it for a conical "
                                       "hopper"});
  }
  return problems;
}

}  // namespace feedflow
