#include "designer/verify/width_bisection.hpp"

#include <cmath>
#include <stdexcept>

namespace feedflow {

const char* to_string(OutletOutcome outcome) {
  return outcome == OutletOutcome::flows ? "flows" : "arches";
}

int bisection_runs(double low, double high, double tolerance) {
  const double halvings = std::ceil(std::log2((high - low) / tolerance));
  return 2 + static_cast<int>(std::max(0.0, halvings));
}

WidthBisection bisect_outlet_width(
    double low, double high, double tolerance,
    const std::function<std::optional<OutletOutcome>(double)>& judge) {
  if (!(low > 0.0 && high > low && tolerance > 0.0))
    throw std::invalid_argument(
        "bisect_outlet_width: needs 0 < low < high and a positive tolerance");
  WidthBisection b;
  const auto ask = [&](double w) {
    const auto outcome = judge(w);
    if (outcome) {
      b.steps.push_back({w, *outcome});
      if (*outcome == OutletOutcome::arches)
        b.arches_at = std::isnan(b.arches_at) ? w : std::max(b.arches_at, w);
      else
        b.flows_at = std::isnan(b.flows_at) ? w : std::min(b.flows_at, w);
    }
    return outcome;
  };
  const auto top = ask(high);
  if (!top) return b;
  if (*top == OutletOutcome::arches) {
    b.end = WidthBisection::End::arches_at_high_edge;
    return b;
  }
  const auto bottom = ask(low);
  if (!bottom) return b;
  if (*bottom == OutletOutcome::flows) {
    b.end = WidthBisection::End::flows_at_low_edge;
    return b;
  }
  while (b.flows_at - b.arches_at > tolerance) {
    if (!ask(0.5 * (b.arches_at + b.flows_at))) return b;
  }
  b.end = WidthBisection::End::bracketed;
  return b;
}

}  // namespace feedflow
