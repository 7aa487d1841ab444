// The default particle snapshot interval of the DEM scenes (designer/simulate/dem_case_settings):
// 20 to 50 snapshots over the planned run, each a whole number of rows; a case's [dem]
// snapshot_interval wins.
#include <gtest/gtest.h>

#include <cmath>

#include "designer/simulate/dem_case_settings.hpp"

namespace feedflow {
namespace {

// The scenes' defaults: the drum's 10 s of rotation at 20 ms rows gives a snapshot every 0.2 s
// (50), the chute's 30 s at 20 ms every 1 s (30), the hopper's 20 s at 10 ms every 0.5 s (40); a
// 0.8 s drum run snapshots every row (40).
TEST(DemSnapshotInterval, ScenesDefaultsGiveTwentyToFiftySnapshots) {
  const Case c;
  EXPECT_DOUBLE_EQ(dem_snapshot_interval(c, 10.0, 0.02), 0.2);
  EXPECT_DOUBLE_EQ(dem_snapshot_interval(c, 30.0, 0.02), 1.0);
  EXPECT_DOUBLE_EQ(dem_snapshot_interval(c, 20.0, 0.01), 0.5);
  EXPECT_DOUBLE_EQ(dem_snapshot_interval(c, 0.8, 0.02), 0.02);
}

// Over asked runs from one row to an hour: never more than 50 snapshots, at least 20 once the run
// has 20 rows, and always a whole number (1, 2 or 5 x 10^n) of rows apart.
TEST(DemSnapshotInterval, AnyRunGetsTwentyToFiftySnapshotsOnRows) {
  const Case c;
  for (const double rows_interval : {0.01, 0.02}) {
    for (double duration = rows_interval; duration <= 3600.0; duration *= 1.07) {
      const double every = dem_snapshot_interval(c, duration, rows_interval);
      const double snapshots = duration / every, rows = every / rows_interval;
      EXPECT_LE(snapshots, 50.0 * (1.0 + 1e-9)) << duration << " s";
      if (duration / rows_interval >= 20.0) {
        EXPECT_GE(snapshots, 20.0 * (1.0 - 1e-9)) << duration << " s";
      }
      EXPECT_NEAR(rows, std::round(rows), 1e-9 * rows) << duration << " s";
      EXPECT_GE(rows, 1.0 - 1e-9) << duration << " s";
    }
  }
}

// A case's [dem] snapshot_interval is used as given, whatever the run's length.
TEST(DemSnapshotInterval, CaseValueWins) {
  Case c;
  c.dem.snapshot_interval = 0.05;
  EXPECT_EQ(dem_snapshot_interval(c, 10.0, 0.02), 0.05);
  EXPECT_EQ(dem_snapshot_interval(c, 0.1, 0.01), 0.05);
}

}  // namespace
}  // namespace feedflow
