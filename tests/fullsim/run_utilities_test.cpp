// Utilities of long runs: the progress line's ETA and the performance block.
#include <gtest/gtest.h>

#include <sstream>

#include "fullsim/common/progress_line.hpp"
#include "fullsim/common/run_report.hpp"

namespace feedflow {
namespace {

// The ETA extrapolates linearly: 25 % done after 10 s leaves 30 s.
TEST(ProgressLine, EtaIsLinearExtrapolation) {
  EXPECT_DOUBLE_EQ(ProgressLine::eta_seconds(10.0, 0.25), 30.0);
  EXPECT_DOUBLE_EQ(ProgressLine::eta_seconds(10.0, 1.0), 0.0);
  EXPECT_LT(ProgressLine::eta_seconds(10.0, 0.0), 0.0);  // unknown before any progress
  EXPECT_EQ(format_duration(3725), "1 h 02 min");
  EXPECT_EQ(format_duration(185), "3 min 05 s");
  EXPECT_EQ(format_duration(-1), "--");
}

// On a (simulated) terminal the line shows percent, amounts with units and the ETA, redraws in
// place, and is cleared at the end; disabled, it prints nothing.
TEST(ProgressLine, DrawsInPlaceAndClears) {
  std::ostringstream out;
  using Clock = ProgressLine::Clock;
  Clock::time_point now{};
  {
    ProgressLine line("DEM", 2.0, "s", out, true);
    line.set_clock([&] { return now; });
    line.set_min_interval(0.0);
    now += std::chrono::seconds(10);
    line.update(0.5);
    EXPECT_NE(out.str().find(" 25.0 %"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("0.5 / 2 s"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("ETA 30 s"), std::string::npos) << out.str();
    EXPECT_EQ(out.str().front(), '\r');
  }
  EXPECT_EQ(out.str().back(), '\r');  // cleared on destruction
  std::ostringstream silent;
  ProgressLine off("DEM", 2.0, "s", silent, false);
  off.update(1.0);
  off.finish();
  EXPECT_TRUE(silent.str().empty());
}

// The performance block lists wall time, figures and each phase with its share; unbooked time
// is "other".
TEST(RunReport, RendersPhasesAndShares) {
  RunReport report("DEM pilot hopper");
  report.set_wall_seconds(10.0);
  report.add_phase_time("pairs", 6.0);
  report.add_phase_time("integration", 2.5);
  report.add_phase_time("pairs", 0.5);
  report.add_figure("particle-steps per second", "1.2e6 1/s");
  const std::string text = report.render();
  EXPECT_NE(text.find("Performance: DEM pilot hopper"), std::string::npos) << text;
  EXPECT_NE(text.find("10 s"), std::string::npos) << text;
  EXPECT_NE(text.find("65.0 %"), std::string::npos) << text;   // pairs 6.5 s of 10 s
  EXPECT_NE(text.find("other"), std::string::npos) << text;
  EXPECT_NE(text.find("10.0 %"), std::string::npos) << text;   // other 1 s
  EXPECT_NE(text.find("1.2e6 1/s"), std::string::npos) << text;
  EXPECT_DOUBLE_EQ(report.phase_seconds("pairs"), 6.5);
  { auto scope = report.time("output"); }
  EXPECT_GE(report.phase_seconds("output"), 0.0);
}

}  // namespace
}  // namespace feedflow
