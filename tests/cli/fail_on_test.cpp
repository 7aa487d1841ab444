// `--fail-on marginal|fail`: scripts and CI get exit code 1 when the verdict is that bad or
// worse, and 0 otherwise; without the flag the verdict never changes the exit code.
#include <gtest/gtest.h>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using namespace feedflow::testing;

namespace {

int design_exit(const fs::path& dir, const std::string& flags) {
  const feedflow::testing::Run r = run_feedflow("design cases/pilot_hopper.toml -q " + flags, dir);
  return r.exit_code;
}

// The pilot hopper at 45 mm is MARGINAL (inside the B_c band), at 100 mm PASS, at 15 mm FAIL:
// --fail-on marginal stops on the first and the last, --fail-on fail on the last only.
TEST(FailOn, ExitCodeFollowsTheVerdict) {
  const fs::path dir = scratch_folder("feedflow_fail_on", true);
  const std::string marginal = "--set hopper.outlet_width=45mm", pass = "--set hopper.outlet_width=100mm",
                    fail = "--set hopper.outlet_width=15mm";
  EXPECT_EQ(design_exit(dir, marginal), 0);
  EXPECT_EQ(design_exit(dir, fail), 0);
  EXPECT_EQ(design_exit(dir, marginal + " --fail-on marginal"), 1);
  EXPECT_EQ(design_exit(dir, marginal + " --fail-on fail"), 0);
  EXPECT_EQ(design_exit(dir, fail + " --fail-on fail"), 1);
  EXPECT_EQ(design_exit(dir, fail + " --fail-on marginal"), 1);
  EXPECT_EQ(design_exit(dir, pass + " --fail-on marginal"), 0);
  EXPECT_EQ(design_exit(dir, pass + " --fail-on sometimes"), 2);
  fs::remove_all(dir);
}

}  // namespace
