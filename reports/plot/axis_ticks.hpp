#pragma once
// Tick positions and labels for a chart axis: "nice" steps (1, 2, 5 x 10^k) that cover the
// data range, labels with just enough decimals, decades on logarithmic axes.
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

}  // namespace feedflow
