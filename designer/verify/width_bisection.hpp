#pragma once
// The narrowest outlet that flows: the flow threshold's bisection (threshold_bisection.hpp) on
// the outlet width, with a full rung as the judge of each width (it flows, or it arches), in the
// hopper's words.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "designer/verify/threshold_bisection.hpp"

namespace feedflow {

enum class OutletOutcome { flows, arches };
const char* to_string(OutletOutcome outcome);

struct BisectionStep {
  double width = 0.0;  // [m]
  OutletOutcome outcome = OutletOutcome::flows;
};

struct WidthBisection {
  enum class End {
    bracketed,            // arches_at < flows_at, narrower than the tolerance
    flows_at_low_edge,    // the band's bottom flows: the critical width is below the band
    arches_at_high_edge,  // the band's top arches: the critical width is above the band
    stopped,              // the judge gave no answer (a run interrupted or failed)
  };
  End end = End::stopped;
  double arches_at = std::numeric_limits<double>::quiet_NaN();  // widest width that arched [m]
  double flows_at = std::numeric_limits<double>::quiet_NaN();   // narrowest width that flowed [m]
  std::vector<BisectionStep> steps;                             // in the order they were judged
};

// `judge` answers for a width, or nothing when its run gave no answer (the bisection stops).
// Throws std::invalid_argument unless 0 < low < high and tolerance > 0.
WidthBisection bisect_outlet_width(
    double low, double high, double tolerance,
    const std::function<std::optional<OutletOutcome>(double)>& judge);

}  // namespace feedflow
