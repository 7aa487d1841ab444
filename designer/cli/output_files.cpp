#include "designer/cli/output_files.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "models/core/errors.hpp"
#include "models/os/atomic_file.hpp"

namespace fs = std::filesystem;

namespace feedflow {

std::string safe_folder_name(std::string_view case_name) {
  std::string name;
  for (const char ch : case_name.substr(0, 100)) {
    const bool keep = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (ch >= '0' && ch <= '9') || ch == '-' || ch == '_' || ch == '.' || ch == '+';
    name += keep ? ch : '_';
  }
  if (name.empty()) return "case";
  if (name.front() == '.') name.front() = '_';
  return name;
}

std::optional<fs::path> output_folder(const CommandOptions& options, const std::string& case_name,
                                      const std::string& suffix, bool folder_needed) {
  if (!options.out.empty()) return fs::path(options.out);
  if (options.json_to_stdout() && !folder_needed) return std::nullopt;
  return fs::path("out") / (safe_folder_name(case_name) + suffix);
}

std::vector<OutputFile> results_files(const std::optional<fs::path>& folder, const std::string& json,
                                      const std::string& summary, const CommandOptions& options) {
  std::vector<OutputFile> files;
  if (folder) {
    files.push_back({*folder / "results.json", json, "--out"});
    files.push_back({*folder / "results.txt", summary, "--out"});
  }
  if (!options.json.empty() && !options.json_to_stdout()) files.push_back({options.json, json, "--json"});
  return files;
}

std::vector<fs::path> write_outputs(const std::vector<OutputFile>& files, const std::string* to_stdout,
                                    bool verbose, OutputFolder* folder) {
  CreatedFolders made;  // parents of files outside the output folder (--json a/b/r.json)
  std::vector<PendingFile> staged;
  staged.reserve(files.size());
  std::string option = "--out";  // what named the step under way, for the error
  try {
    for (const auto& f : files) {
      option = f.option;
      if (f.path.has_parent_path()) made.create(f.path.parent_path());
      staged.emplace_back(f.path, f.content);
    }
    option = "--json";
    std::cout.flush();  // whatever went before stays before
    std::fflush(stdout);
    if (to_stdout) write_all(STDOUT_FILENO, *to_stdout, "the results JSON to stdout (--json -)");
    // Files that cannot be replaced (a FIFO, a device) first: they are the ones that may fail.
    for (const bool special : {true, false})
      for (std::size_t i = 0; i < staged.size(); ++i)
        if (staged[i].is_special() == special) {
          option = files[i].option;
          staged[i].commit();
        }
  } catch (const std::runtime_error& e) {
    staged.clear();  // removes the temporaries
    made.remove_empty();
    if (folder) folder->discard_if_unused();
    throw InputError(option, "", e.what());
  }
  std::vector<fs::path> written;
  for (const auto& s : staged) written.push_back(s.target());
  if (verbose)
    for (const auto& p : written) std::cerr << "feedflow: wrote " << p.string() << '\n';
  return written;
}

void write_json_copy(const std::string& json, const CommandOptions& options) {
  if (options.json.empty()) return;
  std::vector<OutputFile> files;
  if (!options.json_to_stdout()) files.push_back({options.json, json, "--json"});
  write_outputs(files, options.json_to_stdout() ? &json : nullptr, options.verbose, nullptr);
}

}  // namespace feedflow
