// Colour maps, tick values and labels, scale-bar lengths.
#include <gtest/gtest.h>

#include <cmath>

#include "reports/render/colour_map.hpp"
#include "reports/render/legend_overlay.hpp"
#include "reports/plot/axis_ticks.hpp"

namespace feedflow::render {
namespace {

// Viridis runs from dark purple to yellow; out-of-range and NaN inputs are clamped.
TEST(ColourMap, ViridisEndsAndClamping) {
  EXPECT_EQ(viridis(0.0), (Rgb8{68, 1, 84}));
  EXPECT_EQ(viridis(1.0), (Rgb8{253, 231, 37}));
  EXPECT_EQ(viridis(-3.0), viridis(0.0));
  EXPECT_EQ(viridis(7.0), viridis(1.0));
  EXPECT_EQ(viridis(std::nan("")), viridis(0.0));
  // Lightness rises along the map (perceptually ordered).
  int previous = -1;
  for (int k = 0; k <= 20; ++k) {
    const Rgb8 c = viridis(k / 20.0);
    const int luma = 299 * c.r + 587 * c.g + 114 * c.b;
    EXPECT_GT(luma, previous);
    previous = luma;
  }
}

// A colour scale maps lo and hi to the ends of the map and clamps outside them.
TEST(ColourMap, ScaleFractionClamps) {
  const ColourScale s{"speed", "m/s", 1.0, 3.0};
  EXPECT_DOUBLE_EQ(s.fraction(2.0), 0.5);
  EXPECT_DOUBLE_EQ(s.fraction(0.0), 0.0);
  EXPECT_DOUBLE_EQ(s.fraction(9.0), 1.0);
  EXPECT_EQ(s.colour(3.0), viridis(1.0));
  const ColourScale flat{"speed", "m/s", 2.0, 2.0};
  EXPECT_DOUBLE_EQ(flat.fraction(2.0), 0.5);
}

// Neighbouring layer ids get different colours; negative ids are grey.
TEST(ColourMap, LayerColoursDiffer) {
  for (int k = 0; k < 9; ++k) EXPECT_NE(layer_colour(k), layer_colour(k + 1));
  EXPECT_EQ(layer_colour(-1), (Rgb8{160, 160, 160}));
}

// Ticks are round numbers inside the range, for awkward ranges too.
TEST(Ticks, RoundValuesInsideTheRange) {
  const auto unit = ticks_inside(0.0, 1.0, 6);
  ASSERT_EQ(unit.size(), 6u);
  for (std::size_t k = 0; k < unit.size(); ++k) EXPECT_NEAR(unit[k], 0.2 * k, 1e-12);
  const auto awkward = ticks_inside(0.137, 0.912, 6);
  ASSERT_GE(awkward.size(), 3u);
  EXPECT_NEAR(awkward.front(), 0.2, 1e-12);
  EXPECT_NEAR(awkward[1] - awkward[0], 0.1, 1e-12);
  EXPECT_LE(awkward.back(), 0.912);
  EXPECT_EQ(ticks_inside(5.0, 5.0).size(), 1u);
  EXPECT_EQ(tick_label(0.2, 0.1), "0.2");
  EXPECT_EQ(tick_label(1500.0, 500.0), "1500");
  EXPECT_EQ(tick_label(-0.05, 0.05), "-0.05");
}

// Scale-bar lengths are 1, 2 or 5 times a power of ten, labelled in mm below a metre.
TEST(Ticks, ScaleBarLengthsAndLabels) {
  EXPECT_DOUBLE_EQ(round_length_below(0.37), 0.2);
  EXPECT_DOUBLE_EQ(round_length_below(0.07), 0.05);
  EXPECT_DOUBLE_EQ(round_length_below(1.0), 1.0);
  EXPECT_EQ(length_label(0.2), "200 mm");
  EXPECT_EQ(length_label(0.0005), "0.5 mm");
  EXPECT_EQ(length_label(2.0), "2 m");
}

}  // namespace
}  // namespace feedflow::render
