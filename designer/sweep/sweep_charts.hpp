#pragma once
// The design charts of a sweep (plain chart data; reports/ draws them), against the first
// numeric axis, with one curve per value of the next axis (up to eight) where there is one:
// - a solve: the solved value (the smallest passing outlet against the semi-angle);
// - each judged or banded result (q_m against outlet width, with its band when there is one
//   curve, and the limit the judge held it against: the required throughput);
// - two numeric axes of a grid: the verdict map (each point marked pass, marginal or fail;
//   the boundary between the marks is the design boundary, e.g. mass against funnel flow).
// A sampled sweep's charts are scatter plots.
#include <vector>

#include "designer/sweep/sweep_point.hpp"
#include "models/core/chart.hpp"

namespace feedflow {

std::vector<Chart> sweep_charts(const SweepRequest& request, const std::vector<SweepPoint>& points);

}  // namespace feedflow
