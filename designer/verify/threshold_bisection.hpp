#pragma once
// The smallest size at which a full rung's run flows (a hopper's outlet width: narrower arches;
// a layer's thickness on a ramp: thinner comes to rest), found by bisection with the rung as the
// judge of each size, inside a band the reduced rung gives: the band's top is judged first (a
// stop there puts the threshold above the band), then its bottom (a flow there puts it below),
// then the bracket [stops, flows] is halved until it is narrower than the tolerance:
// 2 + ceil(log2(band / tolerance)) runs. A search allowed to reach beyond the band (a floor
// below it, a ceiling above it) widens it instead of ending at an edge: a top that stops becomes
// the bracket's bottom and the top doubles (up to the ceiling); a bottom that flows becomes its
// top and the bottom halves (down to the floor). The judge is assumed monotone in the size; near
// the threshold a stop is a chance event, so the bracket is where the rung's answer changes in
// these runs, not a sharp limit.
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <vector>

namespace feedflow {

struct ThresholdStep {
  double size = 0.0;  // [m]
  bool flows = false;
};

struct ThresholdBisection {
  enum class End {
    bracketed,           // stops_at < flows_at, narrower than the tolerance
    flows_at_low_edge,   // the band's bottom flows: the threshold is below the band
    stops_at_high_edge,  // the band's top stops: the threshold is above the band
    stopped,             // the judge gave no answer (a run interrupted or failed)
  };
  End end = End::stopped;
  double stops_at = std::numeric_limits<double>::quiet_NaN();  // largest size that stopped [m]
  double flows_at = std::numeric_limits<double>::quiet_NaN();  // smallest size that flowed [m]
  std::vector<ThresholdStep> steps;                            // in the order they were judged
};

// `flows` answers for a size, or nothing when its run gave no answer (the bisection stops).
// `floor` and `ceiling` [m]: how far the band may widen (0: not beyond its edge). `grid` [m]
// (0: none): every middle and widened edge is taken to it (the band's edges are asked as given),
// so a search started again from the sizes its runs are named by asks the sizes the first one
// asked, not ones a last digit apart. Throws std::invalid_argument unless 0 < low < high, tolerance
// > 0, floor
// <= low and ceiling >= high (each when given), and grid < tolerance.
ThresholdBisection bisect_flow_threshold(double low, double high, double tolerance,
                                         const std::function<std::optional<bool>(double)>& flows,
                                         double floor = 0.0, double ceiling = 0.0,
                                         double grid = 0.0);

// The number of judged sizes a bisection of [low, high] to `tolerance` takes when it brackets.
int bisection_runs(double low, double high, double tolerance);

// The answer judged earlier at a size within `within` / 2 of `size` [m] (an earlier record keeps a
// size to a nanometre), or none.
template <class Answer>
std::optional<Answer> answered_near(const std::map<double, Answer>& judged, double size,
                                    double within) {
  const auto near = judged.lower_bound(size - 0.5 * within);
  if (near != judged.end() && near->first <= size + 0.5 * within) return near->second;
  return std::nullopt;
}

}  // namespace feedflow
