#pragma once
// Writing the design report of a record: report.pdf and report.html in a folder.
#include <filesystem>
#include <vector>

#include "models/core/design_record.hpp"

namespace feedflow {

// Returns the files written.
std::vector<std::filesystem::path> write_report_files(const std::filesystem::path& folder,
                                                      const DesignRecord& record);

}  // namespace feedflow
