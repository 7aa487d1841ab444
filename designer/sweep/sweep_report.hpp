#pragma once
// A sweep as a record the design report draws (`sweep --report`): its points as the results
// table (a solve's answers with their brackets; a grid's verdicts and governing checks, the
// first 40), the design charts (sweep_charts) and what was varied, as notes.
#include <string>
#include <vector>

#include "designer/sweep/sweep_output.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

// `base`: the case with the fixed values; its inputs head the report, the varied ones showing
// their ranges.
DesignRecord sweep_record(const SweepRequest& request, const Case& base,
                          const std::vector<SweepPoint>& points, const SweepTiming& timing,
                          const std::string& command_line);

}  // namespace feedflow
