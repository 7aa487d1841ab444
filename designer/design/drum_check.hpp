#pragma once
// The rotating-drum design check: Froude number, regime and the dynamic angle of repose in the
// rolling regime, against the case's required regime.
#include "designer/case/case.hpp"
#include "designer/design/verdict_builder.hpp"

namespace feedflow {

void check_drum(const Case& c, const Drum& drum, DesignRecord& record, VerdictBuilder& verdict);

}  // namespace feedflow
