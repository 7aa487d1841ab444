#pragma once
// Pictures of a simulation for its report, drawn off-screen from the run's snapshot files alone
// (so `feedflow report results.json` draws them again): a DEM run's particles coloured by speed
// at three times (first, middle and last snapshot) and by their initial layer (the flow pattern
// at a glance); a CEL run's cells coloured by speed at the same three times, and by density and
// mean stress at the last, with the free surface. The walls are the outline the file keeps.
#include <filesystem>
#include <ostream>
#include <vector>

#include "models/core/design_record.hpp"
#include "reports/document/report_content.hpp"

namespace feedflow {

// The pictures of the run in `run_folder` (particles.h5 and its continuations, or fields.h5);
// empty when the folder holds no snapshot file. Throws std::runtime_error naming the file when
// one cannot be read, NotAvailable when the off-screen renderer is missing.
std::vector<ReportImage> simulation_pictures(const std::filesystem::path& run_folder);

// The pictures of every run a record names (DesignRecord::simulation_runs, relative to
// `results_folder`, where its results file is or will be); a run whose snapshots cannot be
// drawn is named in a warning on `warnings` and left out.
std::vector<ReportImage> record_pictures(const DesignRecord& record,
                                         const std::filesystem::path& results_folder,
                                         std::ostream& warnings);

}  // namespace feedflow
