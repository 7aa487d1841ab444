#pragma once
// The hopper's report charts: critical outlet width against semi-angle, discharge against outlet
// width, the flow-pattern chart and the stresses while emptying, each with the design point.
#include <vector>

#include "designer/design/hopper_assessment.hpp"
#include "models/core/chart.hpp"
#include "models/hopper/flow_pattern.hpp"

namespace feedflow {

std::vector<Chart> hopper_charts(const Hopper& h, const HopperMaterial& m, const ModelChoices& models,
                                 const HopperEvaluation& nominal, const FlowPatternVerdict& pattern);

}  // namespace feedflow
