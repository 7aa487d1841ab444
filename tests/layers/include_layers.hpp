#pragma once
// The layer rules of DESIGN.md as a check over the source tree: arrows point down only
// (designer -> reports, fullsim -> models), reports and fullsim never include each other, and the
// DEM (fullsim/dem) and CEL (fullsim/cel) solvers never include each other. Used by
// layering_test.cpp on the real tree and on small synthetic trees that break each rule.
#include <filesystem>
#include <string>
#include <vector>

namespace feedflow::testing {

// One finding: "fullsim/dem/x.cpp:12 includes reports/y.hpp: fullsim/ may include models/ and
// fullsim/ only".
using LayerViolations = std::vector<std::string>;

// Every #include (quoted or angled) in models/, fullsim/, reports/ and designer/ under `root`
// (*.hpp, *.cpp, *.in) that reaches a layer it may not, or crosses between fullsim/dem and
// fullsim/cel. Relative includes ("../x.hpp") are resolved against the including file.
LayerViolations include_violations(const std::filesystem::path& root);

// Every feedflow_<layer> library that <layer>/CMakeLists.txt links (target_link_libraries) but
// that is not that layer or a layer below it.
LayerViolations link_violations(const std::filesystem::path& root);

// The project files (root-relative) reached from `start` by following #include "..." and, for
// each header reached, its .cpp beside it: what compiling and linking `start` needs.
std::vector<std::string> include_closure(const std::filesystem::path& root,
                                         const std::vector<std::string>& start);

// The source files of models/, fullsim/, reports/ and designer/ under `root` (root-relative,
// sorted) that #include `target` (as written, e.g. "CLI/CLI.hpp").
std::vector<std::string> files_including(const std::filesystem::path& root,
                                         const std::string& target);

}  // namespace feedflow::testing
