#pragma once
// Writing a run's results: results.json and results.txt in the output folder, plus the --json
// copy. Files appear whole or not at all.
#include <filesystem>
#include <string>
#include <vector>

#include "designer/cli/command_options.hpp"

namespace feedflow {

// Returns the files written. With --json -, the JSON also goes to stdout.
std::vector<std::filesystem::path> write_run_outputs(const std::filesystem::path& folder,
                                                     const std::string& json,
                                                     const std::string& summary,
                                                     const CommandOptions& options);

}  // namespace feedflow
