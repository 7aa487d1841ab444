// The sweep's grid: each point answers what `design` answers for the same case and values, on
// any number of threads, and a point the case refuses is kept with its reason.
#include <gtest/gtest.h>

#include <filesystem>

#include <omp.h>

#include "designer/design/design_check.hpp"
#include "designer/sweep/sweep_grid.hpp"

namespace feedflow {
namespace {

SweepRequest pilot_request(std::vector<std::string> vary) {
  SweepRequest r;
  const std::filesystem::path cases = std::filesystem::path(FEEDFLOW_SOURCE_DIR) / "cases";
  r.parsed = parse_case((cases / "pilot_hopper.toml").string());
  r.materials = MaterialLibrary::standard(cases);
  for (const auto& v : vary) r.axes.push_back(parse_sweep_axis(v));
  return r;
}

// Grid points run the last axis fastest and cover every combination once.
TEST(SweepGrid, IndexCoversEveryCombination) {
  const SweepRequest r =
      pilot_request({"hopper.semi_angle=15..40deg/5deg", "hopper.outlet_width=20..100mm:9"});
  ASSERT_EQ(grid_size(r.axes), 54u);
  EXPECT_EQ(grid_index(r.axes, 0), (std::vector<std::size_t>{0, 0}));
  EXPECT_EQ(grid_index(r.axes, 10), (std::vector<std::size_t>{1, 1}));
  EXPECT_EQ(grid_index(r.axes, 53), (std::vector<std::size_t>{5, 8}));
}

// A point's results and verdict are those of the full design check of the case loaded from its
// file with the same overrides (the sweep's parsed-once case and remembered material change
// nothing), bit for bit.
TEST(SweepGrid, APointAnswersAsTheDesignCheck) {
  const SweepRequest r =
      pilot_request({"hopper.semi_angle=15..40deg/5deg", "hopper.outlet_width=20..100mm:9"});
  for (std::size_t n : {0u, 17u, 40u, 53u}) {
    const auto index = grid_index(r.axes, n);
    const SweepPoint p = answer_point(r, index);
    ASSERT_TRUE(p.done) << p.error;
    const std::vector<SetOverride> sets = point_overrides(r, index);
    const DesignRecord full = design_check(load_case(r.parsed.path, sets));
    EXPECT_EQ(p.verdict, full.verdict.status);
    ASSERT_EQ(p.results.size(), full.results.size());
    for (std::size_t k = 0; k < p.results.size(); ++k) {
      EXPECT_EQ(p.results[k].first, full.results[k].first);
      EXPECT_EQ(p.results[k].second.value, full.results[k].second.value) << p.results[k].first;
      EXPECT_EQ(p.results[k].second.low, full.results[k].second.low);
      EXPECT_EQ(p.results[k].second.high, full.results[k].second.high);
    }
  }
}

// Two threads give the same points as one; an outlet wider than the bin is refused by the case
// and kept with the case's reason while the other points are answered.
TEST(SweepGrid, ThreadsGiveTheSamePointsAndRefusalsAreKept) {
  const SweepRequest r =
      pilot_request({"hopper.semi_angle=20..35deg/5deg", "hopper.outlet_width=0.05,0.3,0.7 m"});
  SilentProgress quiet;
  omp_set_num_threads(1);
  const auto one = run_grid(r, quiet);
  omp_set_num_threads(2);
  const auto two = run_grid(r, quiet);
  ASSERT_EQ(one.size(), 12u);
  std::size_t refused = 0;
  for (std::size_t n = 0; n < one.size(); ++n) {
    EXPECT_EQ(one[n].done, two[n].done);
    EXPECT_EQ(one[n].verdict, two[n].verdict);
    EXPECT_EQ(one[n].error, two[n].error);
    if (one[n].done) {
      ASSERT_EQ(one[n].results.size(), two[n].results.size());
      for (std::size_t k = 0; k < one[n].results.size(); ++k)
        EXPECT_EQ(one[n].results[k].second.value, two[n].results[k].second.value);
    } else {
      ++refused;
      EXPECT_NE(one[n].error.find("outlet_width"), std::string::npos) << one[n].error;
    }
  }
  EXPECT_EQ(refused, 4u);  // 0.7 m at each angle: wider than the 0.6 m bin
}

}  // namespace
}  // namespace feedflow
