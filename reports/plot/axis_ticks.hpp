#pragma once
// Tick positions and labels: "nice" steps (1, 2, 5 x 10^k) for chart axes that cover the data
// range, round values inside a fixed range for colour bars, round lengths for scale bars, labels
// with just enough decimals, decades on logarithmic axes.
#include <string>
#include <vector>

namespace feedflow {

struct AxisTicks {
  double lower = 0.0;  // axis range, expanded to whole steps
  double upper = 1.0;
  std::vector<double> values;
  std::vector<std::string> labels;
};

// Linear axis over [data_min, data_max] with about `target` ticks. A degenerate range (equal
// ends) is widened around its value; non-finite input is an std::invalid_argument.
AxisTicks linear_ticks(double data_min, double data_max, int target = 6);

// Logarithmic axis (data_min > 0): ticks at whole decades.
AxisTicks log_ticks(double data_min, double data_max);

// Ticks at multiples of a round step (1, 2 or 5 x 10^k) inside [lo, hi], about `target` of them
// (at least two when lo < hi); {lo} when lo == hi. For a colour bar, whose range is fixed.
std::vector<double> ticks_inside(double lo, double hi, int target = 5);

// The largest 1, 2 or 5 x 10^k not above `limit` (> 0): a scale-bar length.
double round_length_below(double limit);

// A tick label with as many decimals as the step needs ("0.25", "12", "-3.5", "2.5e-05").
std::string tick_label(double value, double step);

}  // namespace feedflow
