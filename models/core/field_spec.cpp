#include "models/core/field_spec.hpp"

#include <cmath>

#include "models/units/quantity_format.hpp"

namespace feedflow {

std::string Range::describe(std::string_view unit) const {
  std::string s;
  if (std::isfinite(lower)) s += std::string(lower_inclusive ? ">= " : "> ") + format_quantity(lower, unit);
  if (std::isfinite(upper)) {
    if (!s.empty()) s += " and ";
    s += std::string(upper_inclusive ? "<= " : "< ") + format_quantity(upper, unit);
  }
  return s.empty() ? "any value" : "must be " + s;
}

}  // namespace feedflow
