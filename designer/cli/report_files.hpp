#pragma once
// The design report of a record: report.pdf and report.html for a folder, to be written with
// the other output files all or none (designer/cli/output_files.hpp). The pictures: the
// hopper's stress map, and those of the simulations the record names (relative to
// `results_folder`, where its results file is); a run whose snapshots cannot be drawn is named
// on stderr.
#include <filesystem>
#include <vector>

#include "designer/cli/output_files.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

std::vector<OutputFile> report_files(const std::filesystem::path& folder, const DesignRecord& record,
                                     const std::filesystem::path& results_folder);

}  // namespace feedflow
