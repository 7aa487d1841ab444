#include "designer/cli/output_files.hpp"

#include <iostream>
#include <stdexcept>

#include "models/core/errors.hpp"
#include "models/os/atomic_file.hpp"

namespace feedflow {

std::vector<std::filesystem::path> write_run_outputs(const std::filesystem::path& folder,
                                                     const std::string& json,
                                                     const std::string& summary,
                                                     const CommandOptions& options) {
  std::vector<std::filesystem::path> written;
  auto write = [&](const std::filesystem::path& path, const std::string& content, const char* key) {
    try {
      write_file_atomically(path, content);
    } catch (const std::runtime_error& e) {
      throw InputError(key, "", e.what());
    }
    written.push_back(path);
  };
  write(folder / "results.json", json, "--out");
  write(folder / "results.txt", summary, "--out");
  if (options.json_to_stdout()) {
    std::cout << json;
    std::cout.flush();
  } else if (!options.json.empty()) {
    write(options.json, json, "--json");
  }
  if (options.verbose)
    for (const auto& p : written) std::cerr << "feedflow: wrote " << p.string() << '\n';
  return written;
}

}  // namespace feedflow
