#pragma once
// The design report of a record: report.pdf and report.html for a folder, to be written with
// the other output files all or none (designer/cli/output_files.hpp). The pictures: the
// hopper's stress map, then `simulation` (designer/simulate/simulation_pictures.hpp: the
// caller draws them, so writing a design report needs no solver code).
#include <filesystem>
#include <vector>

#include "designer/cli/output_files.hpp"
#include "models/core/design_record.hpp"
#include "reports/document/report_content.hpp"

namespace feedflow {

std::vector<OutputFile> report_files(const std::filesystem::path& folder,
                                     const DesignRecord& record,
                                     std::vector<ReportImage> simulation = {});

}  // namespace feedflow
