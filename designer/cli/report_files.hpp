#pragma once
// The design report of a record: report.pdf and report.html for a folder, to be written with
// the other output files all or none (designer/cli/output_files.hpp).
#include <filesystem>
#include <vector>

#include "designer/cli/output_files.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

std::vector<OutputFile> report_files(const std::filesystem::path& folder, const DesignRecord& record);

}  // namespace feedflow
