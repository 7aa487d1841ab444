#pragma once
// The hopper's report charts: critical outlet width against semi-angle, discharge against outlet
// width (one curve per discharge model), the flow-pattern chart, the stresses while emptying and
// the discharged mass against time, each with the design point.
#include <vector>

#include "designer/design/hopper_estimates.hpp"
#include "models/core/chart.hpp"

namespace feedflow {

std::vector<Chart> hopper_charts(const Material& material, const Hopper& h, const HopperAssessment& a);

}  // namespace feedflow
