#pragma once
// Writing a command's output files all or none: results.json and results.txt in the output
// folder, the --json copy (a file, or stdout with --json -), report files, the time series.
// Every file is first staged beside its target (models/os/atomic_file.hpp); then the
// --json - copy goes to stdout; then the files are put in place. A failure before that last
// step leaves no file, no temporary and no folder the command created.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "designer/cli/command_options.hpp"
#include "designer/cli/output_folder.hpp"

namespace feedflow {

struct OutputFile {
  std::filesystem::path path;
  std::string content;
  std::string option;  // what named the place, for errors: "--out" or "--json"
};

// A case name as one folder name: letters, digits and "-_.+" kept, anything else (a slash, a
// space, a control byte) becomes '_', no leading dot (no "..", no hidden folder), at most 100
// bytes; an empty name becomes "case".
std::string safe_folder_name(std::string_view case_name);

// Where a run's files go: --out, else out/<safe case name><suffix>. None when the results JSON
// goes to stdout (--json -) without --out and no other output (`folder_needed`) asks for one.
std::optional<std::filesystem::path> output_folder(const CommandOptions& options,
                                                   const std::string& case_name,
                                                   const std::string& suffix, bool folder_needed);

// results.json and results.txt in `folder` (when given) and the --json FILE copy.
std::vector<OutputFile> results_files(const std::optional<std::filesystem::path>& folder,
                                      const std::string& json, const std::string& summary,
                                      const CommandOptions& options);

// Writes `files` all or none, with `to_stdout` (the --json - copy, when given) between staging
// and committing. Throws InputError naming the option and the file; on failure `folder` (the
// claimed output folder, when given) is discarded if the command created it and it is empty.
// Returns the files written (a link's target where a path was a link).
std::vector<std::filesystem::path> write_outputs(const std::vector<OutputFile>& files,
                                                 const std::string* to_stdout, bool verbose,
                                                 OutputFolder* folder);

// The --json copy alone (materials, cases): to FILE, or to stdout with --json -; nothing
// without --json.
void write_json_copy(const std::string& json, const CommandOptions& options);

}  // namespace feedflow
