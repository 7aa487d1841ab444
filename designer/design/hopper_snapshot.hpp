#pragma once
// A rendered picture of the hopper for its report: the cross-section with the material filled to
// its height, coloured by the mean vertical stress while emptying (Janssen in the bin, the slice
// below). Built from the design record's resolved inputs, so `feedflow report results.json`
// draws it too.
#include <optional>

#include "models/core/design_record.hpp"
#include "reports/document/report_content.hpp"

namespace feedflow {

// Empty for records that are not hoppers or lack the inputs it needs.
std::optional<ReportImage> hopper_stress_snapshot(const DesignRecord& record);

}  // namespace feedflow
