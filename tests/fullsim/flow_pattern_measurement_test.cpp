// The flow-pattern line every rung measures (fullsim/common/flow_pattern_measurement.hpp).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <limits>

#include "fullsim/common/flow_pattern_measurement.hpp"

namespace feedflow {
namespace {

// A profile from the centre (1 m/s) out to the wall moving at `wall` m/s, `points` long.
SpeedProfile line(double wall, int points) {
  SpeedProfile p;
  for (int k = 0; k < points; ++k) {
    p.offset.push_back(0.01 * k);
    p.speed.push_back(1.0 + (wall - 1.0) * k / (points - 1.0));
  }
  return p;
}

// Mass flow when the wall moves at more than a tenth of the centre; funnel flow when it stands;
// an empty line, a centre at rest or a line of one or two points (a funnel that emptied the
// line's centre) measures nothing.
TEST(FlowPatternMeasurement, WallToCentreSpeedRatio) {
  EXPECT_EQ(wall_to_centre_speed_ratio(line(0.5, 5)).label(), "mass");
  EXPECT_EQ(wall_to_centre_speed_ratio(line(0.02, 5)).label(), "funnel");
  EXPECT_NEAR(wall_to_centre_speed_ratio(line(0.5, 5)).ratio, 0.5, 1e-15);
  EXPECT_EQ(wall_to_centre_speed_ratio(line(0.5, 5)).stagnant_width, 0.0);  // all moves
  // 1 -> 0.02 m/s over 0-40 mm: 0.1 m/s is reached at 36.7 mm, so the points at 40 mm (0.02)
  // stand and the one at 30 mm (0.265) moves: a dead zone of 10 mm.
  EXPECT_NEAR(wall_to_centre_speed_ratio(line(0.02, 5)).stagnant_width, 0.01, 1e-15);
  EXPECT_FALSE(wall_to_centre_speed_ratio(SpeedProfile{}).measured);
  EXPECT_FALSE(wall_to_centre_speed_ratio(SpeedProfile{{0.0, 0.1}, {0.0, 0.3}}).measured);
  EXPECT_FALSE(wall_to_centre_speed_ratio(line(0.5, 2)).measured);
  EXPECT_FALSE(wall_to_centre_speed_ratio(SpeedProfile{{0.05}, {0.2}}).measured);
  EXPECT_TRUE(wall_to_centre_speed_ratio(line(0.5, 3)).measured);
}

// Averaged over the window's samples, offset by offset; an outer point that had material in
// fewer than half of the samples (the surface sinking below the line at the end) does not count,
// and the series survives a checkpoint.
TEST(FlowPatternMeasurement, SeriesAveragesOverTheWindow) {
  SpeedProfileSeries s;
  s.add(0.0, line(0.9, 5));   // before the window
  s.add(1.0, line(0.4, 5));
  s.add(1.1, line(0.6, 5));
  s.add(1.2, line(0.5, 6));   // one sample reaches a sixth point (speed 0.5)
  s.add(1.3, line(0.5, 5));
  const WallSpeedRatio r = s.ratio(1.0, 1.3);
  ASSERT_TRUE(r.measured);
  // The fifth point (0.04 m): 0.4, 0.6, 0.6 (k = 4 of 6 at 0.5 wall: 1 - 0.5 x 4/5), 0.5.
  EXPECT_NEAR(r.ratio, (0.4 + 0.6 + 0.6 + 0.5) / 4.0, 1e-12);
  const auto file = std::filesystem::temp_directory_path() / ("feedflow_flowline_" + std::to_string(::getpid()) + ".h5");
  {
    Hdf5File f(file, Hdf5File::Mode::create);
    s.save(f, "/scene/flow_line");
    f.close();
  }
  SpeedProfileSeries back;
  back.restore(Hdf5File(file, Hdf5File::Mode::read), "/scene/flow_line");
  std::filesystem::remove(file);
  EXPECT_EQ(back.size(), 5u);
  EXPECT_EQ(back.ratio(1.0, 1.3).ratio, r.ratio);
  EXPECT_EQ(back.ratio(0.0, std::numeric_limits<double>::infinity()).ratio,
            s.ratio(0.0, std::numeric_limits<double>::infinity()).ratio);
}

// A line that empties within the window (the surface sinking through it: 6 points, then 2,
// then none) measures nothing over the whole window, but is covered until the last sample with
// at least half its fullest count, and measures over that part.
TEST(FlowPatternMeasurement, CoveredUntilTheSurfaceReachesTheLine) {
  SpeedProfileSeries s;
  for (int k = 0; k < 10; ++k) s.add(0.1 * k, line(0.5, 6));  // t = 0 .. 0.9 s, covered
  s.add(1.0, line(0.5, 3));                                    // half of 6: still covered
  s.add(1.1, line(0.5, 2));                                    // the surface is at the line
  for (int k = 12; k < 30; ++k) s.add(0.1 * k, SpeedProfile{});  // empty
  EXPECT_FALSE(s.ratio(0.0, 2.9).measured);
  EXPECT_NEAR(s.covered_until(0.0, 2.9), 1.0, 1e-12);
  EXPECT_NEAR(s.covered_until(0.0, 0.55), 0.55, 1e-12);  // covered to the window's end
  EXPECT_NEAR(s.covered_until(1.15, 2.9), 2.9, 1e-12);   // nothing in it to lose
  const WallSpeedRatio r = s.ratio(0.0, s.covered_until(0.0, 2.9));
  ASSERT_TRUE(r.measured);
  EXPECT_NEAR(r.ratio, 0.5, 1e-12);  // the wall point (k = 5 of 6) in the ten full samples
}

}  // namespace
}  // namespace feedflow
