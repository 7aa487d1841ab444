#pragma once
// `--solve-for`: at one point of the other axes, the value of the solved key where the target
// starts or stops being met. The key's values are scanned in order (sorted); the first place the
// condition changes is bisected until the bracket is within the tolerance. The answer is the
// bracket's meeting end (the smallest outlet that passes is never an outlet that fails), with
// what sets the boundary just beyond it. The scan's other changes are counted, not solved.
#include <vector>

#include "designer/sweep/sweep_point.hpp"

namespace feedflow {

// The tolerance when none is given: a thousandth of the scanned span (SI).
double default_solve_tolerance(const SweepAxis& axis);

// Solves at one point of `request.axes` (which do not hold the solved key). The point's verdict
// and results are those at the answer; a point where the target is never met is `done = false`
// with the nearest scanned value's verdict and reason in `error`.
SweepPoint solve_point(const SweepRequest& request, const std::vector<std::size_t>& index);

}  // namespace feedflow
