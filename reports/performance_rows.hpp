#pragma once
// A simulation's performance block as rows people read, for results.txt and the report: the
// wall time and each figure (name, value), then each phase with its time and its share of the
// wall time, and the time booked to no phase as "other".
#include <array>
#include <string>
#include <vector>

#include "models/core/design_record.hpp"

namespace feedflow {

using PerformanceRow =
    std::array<std::string, 3>;  // name, value or time, share ("41.2 %"; empty for a figure)

std::vector<PerformanceRow> performance_rows(const PerformanceBlock& block);

}  // namespace feedflow
