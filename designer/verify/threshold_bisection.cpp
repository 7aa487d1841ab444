#include "designer/verify/threshold_bisection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace feedflow {

int bisection_runs(double low, double high, double tolerance) {
  const double halvings = std::ceil(std::log2((high - low) / tolerance));
  return 2 + static_cast<int>(std::max(0.0, halvings));
}

ThresholdBisection bisect_flow_threshold(double low, double high, double tolerance,
                                         const std::function<std::optional<bool>(double)>& flows,
                                         double floor, double ceiling) {
  if (floor == 0.0) floor = low;
  if (ceiling == 0.0) ceiling = high;
  if (!(low > 0.0 && high > low && tolerance > 0.0 && floor > 0.0 && floor <= low &&
        ceiling >= high))
    throw std::invalid_argument(
        "bisect_flow_threshold: needs 0 < floor <= low < high <= ceiling and a positive "
        "tolerance");
  using End = ThresholdBisection::End;
  ThresholdBisection b;
  const auto ask = [&](double size) {
    const auto answer = flows(size);
    if (answer) {
      b.steps.push_back({size, *answer});
      if (*answer)
        b.flows_at = std::isnan(b.flows_at) ? size : std::min(b.flows_at, size);
      else
        b.stops_at = std::isnan(b.stops_at) ? size : std::max(b.stops_at, size);
    }
    return answer;
  };
  // The top, doubled while it stops and the ceiling allows.
  for (double top = high;; top = std::min(2.0 * top, ceiling)) {
    const auto answer = ask(top);
    if (!answer) return b;
    if (*answer) break;
    if (top >= ceiling) {
      b.end = End::stops_at_high_edge;
      return b;
    }
  }
  // The bottom, halved while it flows and the floor allows (a top that stopped is a bottom).
  if (std::isnan(b.stops_at))
    for (double bottom = low;; bottom = std::max(0.5 * bottom, floor)) {
      const auto answer = ask(bottom);
      if (!answer) return b;
      if (!*answer) break;
      if (bottom <= floor) {
        b.end = End::flows_at_low_edge;
        return b;
      }
    }
  while (b.flows_at - b.stops_at > tolerance)
    if (!ask(0.5 * (b.stops_at + b.flows_at))) return b;
  b.end = End::bracketed;
  return b;
}

}  // namespace feedflow
