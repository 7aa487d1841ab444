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
                                         double floor, double ceiling, double grid) {
  if (floor == 0.0) floor = low;
  if (ceiling == 0.0) ceiling = high;
  if (!(low > 0.0 && high > low && tolerance > 0.0 && floor > 0.0 && floor <= low &&
        ceiling >= high && grid >= 0.0 && grid < tolerance))
    throw std::invalid_argument(
        "bisect_flow_threshold: needs 0 < floor <= low < high <= ceiling, a positive "
        "tolerance and a grid below it");
  // A middle or a widened edge to the grid (the band's edges are asked as given): a size a
  // quarter step above a grid point or less goes down to it, so the middle of two grid points
  // (half a step off, give or take rounding) always goes down.
  const auto on_grid = [grid](double size) {
    return grid > 0.0 ? std::floor(size / grid + 0.25) * grid : size;
  };
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
  for (double top = high;; top = std::min(on_grid(2.0 * top), ceiling)) {
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
    for (double bottom = low;; bottom = std::max(on_grid(0.5 * bottom), floor)) {
      const auto answer = ask(bottom);
      if (!answer) return b;
      if (!*answer) break;
      if (bottom <= floor) {
        b.end = End::flows_at_low_edge;
        return b;
      }
    }
  while (b.flows_at - b.stops_at > tolerance) {
    const double middle = on_grid(0.5 * (b.stops_at + b.flows_at));
    if (middle <= b.stops_at || middle >= b.flows_at) break;  // no grid point between them
    if (!ask(middle)) return b;
  }
  b.end = End::bracketed;
  return b;
}

}  // namespace feedflow
