#pragma once
// What a chute's run on the continuum rung will cost before it is made, for `design --verify`:
// the wall time the shipped bench table measured for the seed's inclined plane (29.5 deg) at the
// CEL level nearest the case's cell size, scaled as h^-3 (cells h^-2, steps h^-1) when the cell
// sizes differ. The seed's plane stands for the case: a longer ramp or bin costs more.
#include <optional>
#include <string>

#include "designer/case/case.hpp"

namespace feedflow {

struct CelRunEstimate {
  double seconds = 0.0;  // [s] wall
  std::string
      text;  // "about 39 s on 2 cores, as the seed's inclined plane took on 20 mm cells ..."
};

// On `cell` [m], else the case's cell size; none when the shipped table has no measured CEL
// level of the plane.
std::optional<CelRunEstimate> estimate_cel_chute_run(const Case& c,
                                                     std::optional<double> cell = std::nullopt);

// The cell size [m] of the cheapest CEL level of the seed's plane whose measured error against
// the table's reference is within `tolerance` (what `--verify auto` runs a chute on); none, with
// the reason in `why`, when the reference's own error bar is wider or no level meets it.
std::optional<double> chute_cell_within(double tolerance, std::string& why);

}  // namespace feedflow
