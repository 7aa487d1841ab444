// The layers of DESIGN.md hold in the source tree: no include reaches up a layer, DEM and CEL
// never include each other, each folder's CMakeLists links only the layers below it, writing
// the design command's files needs no solver, and one file compiles the command-line parser.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/layers/include_layers.hpp"

namespace feedflow::testing {
namespace {
namespace fs = std::filesystem;

const fs::path kRoot = FEEDFLOW_SOURCE_ROOT;

std::string listed(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& line : lines) s += "\n  " + line;
  return s;
}

// A throw-away source tree for the checker's own tests.
class SyntheticTree {
 public:
  explicit SyntheticTree(const std::string& name)
      : root_(fs::temp_directory_path() / ("feedflow_layers_" + name)) {
    fs::remove_all(root_);
  }
  ~SyntheticTree() { fs::remove_all(root_); }
  void write(const std::string& file, const std::string& text) const {
    fs::create_directories((root_ / file).parent_path());
    std::ofstream(root_ / file) << text;
  }
  const fs::path& root() const { return root_; }

 private:
  fs::path root_;
};

// The real tree: every include of models/, fullsim/, reports/ and designer/ points down or
// sideways within its layer, and fullsim/dem and fullsim/cel never include each other.
TEST(Layers, NoIncludeReachesUpAndDemAndCelStayApart) {
  ASSERT_TRUE(fs::is_directory(kRoot / "models")) << kRoot;
  const auto violations = include_violations(kRoot);
  EXPECT_TRUE(violations.empty()) << listed(violations);
}

// The real tree: models links no feedflow library, fullsim and reports link models only,
// designer any of them.
TEST(Layers, CMakeLinksOnlyTheLayersBelow) {
  const auto violations = link_violations(kRoot);
  EXPECT_TRUE(violations.empty()) << listed(violations);
}

// Writing the results and the report of `feedflow design` compiles and links without the
// solver layer: the include closure of the file writers holds no fullsim/ file.
TEST(Layers, WritingDesignFilesNeedsNoSolver) {
  const auto closure =
      include_closure(kRoot, {"designer/cli/output_files.cpp", "designer/cli/report_files.cpp"});
  ASSERT_TRUE(std::count(closure.begin(), closure.end(), "models/os/atomic_file.cpp") == 1)
      << listed(closure);
  std::vector<std::string> solver;
  std::copy_if(closure.begin(), closure.end(), std::back_inserter(solver),
               [](const std::string& f) { return f.starts_with("fullsim/"); });
  EXPECT_TRUE(solver.empty()) << listed(solver);
}

// The command-line parser (CLI11, header-only and slow to compile) is seen by one file,
// designer/cli/command_line.cpp, behind designer/cli/command_line.hpp: the subcommand files
// declare their options through that interface and are not each compiled with the parser.
TEST(Layers, OneFileSeesTheCommandLineParser) {
  const std::vector<std::string> expected = {"designer/cli/command_line.cpp"};
  EXPECT_EQ(files_including(kRoot, "CLI/CLI.hpp"), expected);
  // The search finds an include of the parser where it is (so the check above can fail).
  const SyntheticTree tree("parser");
  tree.write("designer/cli/x_command.cpp", "#include <CLI/CLI.hpp>\n");
  tree.write("designer/cli/y_command.cpp", "#include \"designer/cli/command_line.hpp\"\n");
  EXPECT_EQ(files_including(tree.root(), "CLI/CLI.hpp"),
            std::vector<std::string>{"designer/cli/x_command.cpp"});
}

// The checker catches each kind of violation (so the real-tree tests above can fail): a model
// including the solver layer, reports including fullsim (angled and relative), DEM including
// CEL, and a layer including the tests; a tree that keeps the rules passes.
TEST(Layers, CheckerFindsEachKindOfViolation) {
  const SyntheticTree good("good");
  good.write("models/core/a.hpp", "#pragma once\n#include <vector>\n#include \"CLI/CLI.hpp\"\n");
  good.write("fullsim/dem/b.cpp",
             "#include \"fullsim/common/c.hpp\"\n#include \"models/core/a.hpp\"\n");
  good.write("designer/d.cpp", "#include \"reports/e.hpp\"\n#include \"fullsim/dem/b.hpp\"\n");
  EXPECT_TRUE(include_violations(good.root()).empty()) << listed(include_violations(good.root()));

  const SyntheticTree bad("bad");
  bad.write("models/hopper/m.cpp",
            "#include \"models/core/a.hpp\"\n#include \"fullsim/dem/x.hpp\"\n");
  bad.write("reports/r.hpp", "#pragma once\n#include <fullsim/common/y.hpp>\n");
  bad.write("reports/plot/p.cpp", "#include \"../../designer/z.hpp\"\n");
  bad.write("fullsim/dem/engine.cpp", "  #  include \"fullsim/cel/solver.hpp\"\n");
  bad.write("fullsim/cel/s.cpp", "#include \"fullsim/dem/particles.hpp\"\n");
  bad.write("fullsim/common/t.cpp", "#include \"tests/support/pine.hpp\"\n");
  const auto found = include_violations(bad.root());
  const std::vector<std::string> expected = {
      "fullsim/cel/s.cpp:1 includes fullsim/dem/particles.hpp: the DEM and CEL solvers never "
      "include each other",
      "fullsim/common/t.cpp:1 includes tests/support/pine.hpp: fullsim/ may include models/ and "
      "fullsim/ only",
      "fullsim/dem/engine.cpp:1 includes fullsim/cel/solver.hpp: the DEM and CEL solvers never "
      "include each other",
      "models/hopper/m.cpp:2 includes fullsim/dem/x.hpp: models/ may include models/ only",
      "reports/plot/p.cpp:1 includes designer/z.hpp: reports/ may include models/ and reports/ "
      "only",
      "reports/r.hpp:2 includes fullsim/common/y.hpp: reports/ may include models/ and reports/ "
      "only",
  };
  std::vector<std::string> sorted = found;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, expected) << listed(found);
}

// The link check catches a layer that links one above it, and passes links downwards.
TEST(Layers, LinkCheckerFindsALinkUpwards) {
  const SyntheticTree tree("links");
  tree.write("models/CMakeLists.txt", "target_link_libraries(feedflow_models PUBLIC GSL::gsl)\n");
  tree.write("reports/CMakeLists.txt",
             "target_link_libraries(feedflow_reports PUBLIC feedflow_models\n"
             "                      feedflow_fullsim)\n");
  tree.write("designer/CMakeLists.txt",
             "target_link_libraries(feedflow_designer PUBLIC feedflow_reports feedflow_fullsim)\n");
  const auto found = link_violations(tree.root());
  ASSERT_EQ(found.size(), 1u) << listed(found);
  EXPECT_EQ(found[0],
            "reports/CMakeLists.txt links feedflow_fullsim: reports/ may link models/ and "
            "reports/ only");
}

}  // namespace
}  // namespace feedflow::testing
