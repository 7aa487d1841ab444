#include "designer/verify/width_bisection.hpp"

namespace feedflow {

const char* to_string(OutletOutcome outcome) {
  return outcome == OutletOutcome::flows ? "flows" : "arches";
}

WidthBisection bisect_outlet_width(
    double low, double high, double tolerance,
    const std::function<std::optional<OutletOutcome>(double)>& judge) {
  const ThresholdBisection t =
      bisect_flow_threshold(low, high, tolerance, [&](double w) -> std::optional<bool> {
        const auto outcome = judge(w);
        if (!outcome) return std::nullopt;
        return *outcome == OutletOutcome::flows;
      });
  using End = ThresholdBisection::End;
  WidthBisection b;
  b.end = t.end == End::bracketed            ? WidthBisection::End::bracketed
          : t.end == End::flows_at_low_edge  ? WidthBisection::End::flows_at_low_edge
          : t.end == End::stops_at_high_edge ? WidthBisection::End::arches_at_high_edge
                                             : WidthBisection::End::stopped;
  b.arches_at = t.stops_at;
  b.flows_at = t.flows_at;
  for (const ThresholdStep& s : t.steps)
    b.steps.push_back({s.size, s.flows ? OutletOutcome::flows : OutletOutcome::arches});
  return b;
}

}  // namespace feedflow
