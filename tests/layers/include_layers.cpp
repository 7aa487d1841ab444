#include "tests/layers/include_layers.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>

namespace feedflow::testing {
namespace fs = std::filesystem;
namespace {

// Each layer and the top-level folders its files may include (DESIGN.md "Layers").
const std::map<std::string, std::vector<std::string>> kMayInclude = {
    {"models", {"models"}},
    {"fullsim", {"models", "fullsim"}},
    {"reports", {"models", "reports"}},
    {"designer", {"models", "fullsim", "reports", "designer"}},
};
// Folders that hold project headers; an include whose first folder is not one of them (a
// library's "CLI/CLI.hpp") is not the project's business here.
const std::set<std::string> kProjectFolders = {"models",   "fullsim", "reports",
                                               "designer", "tests",   "cases"};
// Solver folders that never include each other.
const std::pair<std::string_view, std::string_view> kSeparated[] = {
    {"fullsim/dem/", "fullsim/cel/"},
    {"fullsim/cel/", "fullsim/dem/"},
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string first_folder(const std::string& path) { return path.substr(0, path.find('/')); }

std::string allowed_text(const std::vector<std::string>& folders) {
  std::string s;
  for (std::size_t i = 0; i < folders.size(); ++i)
    s += (i == 0 ? "" : i + 1 == folders.size() ? " and " : ", ") + folders[i] + "/";
  return s + " only";
}

struct IncludeLine {
  int line;
  std::string target;  // root-relative when it names a project file
};

// The includes of one file, relative ones resolved to root-relative paths.
std::vector<IncludeLine> includes_of(const fs::path& root, const std::string& file) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*[<"]([^">]+)[">])");
  std::vector<IncludeLine> found;
  std::istringstream text(read_text(root / file));
  std::string line;
  for (int number = 1; std::getline(text, line); ++number) {
    std::smatch m;
    if (!std::regex_search(line, m, kInclude)) continue;
    std::string target = m[1];
    if (target.starts_with("./") || target.starts_with("../") ||
        (target.find('/') == std::string::npos &&
         fs::exists(root / fs::path(file).parent_path() / target))) {
      target = (fs::path(file).parent_path() / target).lexically_normal().generic_string();
    }
    found.push_back({number, target});
  }
  return found;
}

bool is_source(const fs::path& path) {
  const std::string ext = path.extension().string();
  return ext == ".hpp" || ext == ".cpp" || ext == ".h" || ext == ".in";
}

// The source files of one layer folder, root-relative and sorted.
std::vector<std::string> layer_sources(const fs::path& root, const std::string& layer) {
  std::vector<std::string> files;
  if (!fs::is_directory(root / layer)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(root / layer))
    if (entry.is_regular_file() && is_source(entry.path()))
      files.push_back(fs::relative(entry.path(), root).generic_string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

LayerViolations include_violations(const fs::path& root) {
  LayerViolations violations;
  for (const auto& [layer, allowed] : kMayInclude) {
    for (const std::string& file : layer_sources(root, layer)) {
      for (const IncludeLine& include : includes_of(root, file)) {
        const std::string where =
            file + ":" + std::to_string(include.line) + " includes " + include.target + ": ";
        const std::string folder = first_folder(include.target);
        if (include.target.starts_with("..")) {
          violations.push_back(where + "it leaves the source tree");
          continue;
        }
        if (kProjectFolders.count(folder) != 0 &&
            std::find(allowed.begin(), allowed.end(), folder) == allowed.end()) {
          violations.push_back(where + layer + "/ may include " + allowed_text(allowed));
          continue;
        }
        for (const auto& [from, to] : kSeparated) {
          if (file.starts_with(from) && include.target.starts_with(to))
            violations.push_back(where + "the DEM and CEL solvers never include each other");
        }
      }
    }
  }
  return violations;
}

LayerViolations link_violations(const fs::path& root) {
  static const std::regex kLink(R"(target_link_libraries\s*\(([^)]*)\))");
  static const std::regex kLibrary(R"(\bfeedflow_(models|fullsim|reports|designer)\b)");
  LayerViolations violations;
  for (const auto& [layer, allowed] : kMayInclude) {
    const fs::path cmake = root / layer / "CMakeLists.txt";
    if (!fs::exists(cmake)) continue;
    const std::string text = read_text(cmake);
    for (auto call = std::sregex_iterator(text.begin(), text.end(), kLink);
         call != std::sregex_iterator(); ++call) {
      const std::string arguments = (*call)[1];
      for (auto lib = std::sregex_iterator(arguments.begin(), arguments.end(), kLibrary);
           lib != std::sregex_iterator(); ++lib) {
        const std::string linked = (*lib)[1];
        if (std::find(allowed.begin(), allowed.end(), linked) == allowed.end())
          violations.push_back(layer + "/CMakeLists.txt links feedflow_" + linked + ": " + layer +
                               "/ may link " + allowed_text(allowed));
      }
    }
  }
  return violations;
}

std::vector<std::string> include_closure(const fs::path& root,
                                         const std::vector<std::string>& start) {
  std::set<std::string> seen;
  std::vector<std::string> stack(start.begin(), start.end());
  while (!stack.empty()) {
    const std::string file = stack.back();
    stack.pop_back();
    if (!fs::is_regular_file(root / file) || !seen.insert(file).second) continue;
    for (const IncludeLine& include : includes_of(root, file)) {
      stack.push_back(include.target);
      if (include.target.ends_with(".hpp"))
        stack.push_back(include.target.substr(0, include.target.size() - 4) + ".cpp");
    }
  }
  return {seen.begin(), seen.end()};
}

std::vector<std::string> files_including(const fs::path& root, const std::string& target) {
  std::vector<std::string> found;
  for (const auto& entry : kMayInclude)
    for (const std::string& file : layer_sources(root, entry.first)) {
      const auto includes = includes_of(root, file);
      if (std::any_of(includes.begin(), includes.end(),
                      [&](const IncludeLine& include) { return include.target == target; }))
        found.push_back(file);
    }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace feedflow::testing
