// The hopper picture of the design report: rendered from the record's inputs alone.
#include <gtest/gtest.h>

#include <cairo.h>

#include "designer/case/case_loader.hpp"
#include "designer/design/design_check.hpp"
#include "designer/design/hopper_snapshot.hpp"

namespace feedflow {
namespace {

// A hopper record gives a 1000 x 800 PNG with a caption naming the fill and the stress; a drum
// record gives none.
TEST(HopperSnapshot, RenderedForHoppersOnly) {
  const DesignRecord hopper = design_check(load_case("cases/pilot_hopper.toml"));
  const auto picture = hopper_stress_snapshot(hopper);
  ASSERT_TRUE(picture.has_value());
  ASSERT_GT(picture->png.size(), 1000u);
  EXPECT_EQ(picture->png.substr(1, 3), "PNG");
  EXPECT_NE(picture->caption.find("0.68 m"), std::string::npos) << picture->caption;
  EXPECT_NE(picture->caption.find("vertical stress"), std::string::npos);
  EXPECT_FALSE(hopper_stress_snapshot(design_check(load_case("cases/rotating_drum_20rpm.toml"))).has_value());
  DesignRecord stripped = hopper;
  stripped.inputs.clear();  // an old or foreign results file: no picture, no error
  EXPECT_FALSE(hopper_stress_snapshot(stripped).has_value());
}

}  // namespace
}  // namespace feedflow
