#pragma once
// The human-readable summary of a design record: what `feedflow design` prints and writes to
// results.txt. Every number carries its unit.
#include <string>

#include "models/core/design_record.hpp"

namespace feedflow {

std::string text_summary(const DesignRecord& record);

}  // namespace feedflow
