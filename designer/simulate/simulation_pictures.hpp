#pragma once
// Pictures of a simulation for its report, drawn off-screen from the run's snapshot files alone
// (so `feedflow report results.json` draws them again): a DEM run's particles coloured by speed
// at three times (first, middle and last snapshot) and by their initial layer (the flow pattern
// at a glance); a CEL run's cells coloured by speed at the same three times, and by density and
// mean stress at the last, with the free surface. The walls are the outline the file keeps.
#include <filesystem>
#include <vector>

#include "reports/document/report_content.hpp"

namespace feedflow {

// The pictures of the run in `run_folder` (particles.h5 and its continuations, or fields.h5);
// empty when the folder holds no snapshot file. Throws std::runtime_error naming the file when
// one cannot be read, NotAvailable when the off-screen renderer is missing.
std::vector<ReportImage> simulation_pictures(const std::filesystem::path& run_folder);

}  // namespace feedflow
