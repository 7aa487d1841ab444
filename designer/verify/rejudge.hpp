#pragma once
// Judging a record again after a verification put a full rung's answers in its results: the
// judge's findings on the new estimates, the design check's notes the judge does not make
// itself (each once), and the reasons earlier verifications added, in that order.
#include "designer/case/case.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

void rejudge(const Case& c, DesignRecord& record);

}  // namespace feedflow
