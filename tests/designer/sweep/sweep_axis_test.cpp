// `--vary KEY=RANGE`: steps, counts, log spacing, lists and words, with units on either end,
// and every malformed range refused naming --vary.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designer/sweep/sweep_axis.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::string axis_refusal(const std::string& text) {
  try {
    parse_sweep_axis(text);
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "--vary") << text;
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return "";
}

// A step range keeps its end when it falls on a step; the values are handed to the case in the
// unit written and carried in SI.
TEST(SweepAxis, StepRangeInTheWrittenUnit) {
  const SweepAxis a = parse_sweep_axis("hopper.semi_angle=15..40deg/5deg");
  EXPECT_EQ(a.case_key, "hopper.semi_angle");
  EXPECT_EQ(a.unit, "deg");
  ASSERT_EQ(a.values.size(), 6u);
  EXPECT_EQ(a.values[0].text, "15 deg");
  EXPECT_EQ(a.values[5].text, "40 deg");
  EXPECT_NEAR(*a.values[3].si, 30 * kDeg, 1e-15);
  // 0.1 steps that do not sum exactly still reach the end.
  EXPECT_EQ(parse_sweep_axis("hopper.fill_height=0.1..0.5m/0.1m").values.size(), 5u);
  // The unit may sit on one end only, or on the step.
  EXPECT_EQ(parse_sweep_axis("hopper.semi_angle=15deg..40/5").values.size(), 6u);
  EXPECT_EQ(parse_sweep_axis("hopper.semi_angle=15..40/5deg").values.back().text, "40 deg");
}

// A count spaces the values evenly, ends included; "log" spaces them evenly in the logarithm;
// ends in two units of one dimension are taken in the first one written.
TEST(SweepAxis, CountAndLogRanges) {
  const SweepAxis a = parse_sweep_axis("hopper.outlet_width=20..100mm:9");
  ASSERT_EQ(a.values.size(), 9u);
  EXPECT_EQ(a.values[1].text, "30 mm");
  EXPECT_NEAR(*a.values[8].si, 0.1, 1e-15);
  const SweepAxis g = parse_sweep_axis("hopper.outlet_width=1..100 mm:3log");
  ASSERT_EQ(g.values.size(), 3u);
  EXPECT_NEAR(*g.values[1].si, 0.01, 1e-15);
  const SweepAxis m = parse_sweep_axis("hopper.outlet_width=20mm..0.1m:3");
  EXPECT_EQ(m.unit, "mm");
  EXPECT_EQ(m.values[1].text, "60 mm");
}

// Lists: a unit at the end applies to the items without one; words for labels and materials.
TEST(SweepAxis, ListsOfNumbersAndWords) {
  const SweepAxis a = parse_sweep_axis("hopper.fill_height=0.2,0.3,0.5 m");
  ASSERT_EQ(a.values.size(), 3u);
  EXPECT_EQ(a.values[2].text, "0.5 m");
  EXPECT_NEAR(*a.values[0].si, 0.2, 1e-15);
  const SweepAxis w = parse_sweep_axis("material=loblolly_pine,other_pine");
  EXPECT_EQ(w.case_key, "case.material");
  EXPECT_FALSE(w.numeric());
  EXPECT_EQ(w.values[1].text, "other_pine");
  EXPECT_EQ(parse_sweep_axis("hopper.shape=wedge,conical").values.size(), 2u);
  // A dimensionless key takes bare numbers.
  EXPECT_EQ(parse_sweep_axis("design.outlet_safety_factor=1..1.5:6").values[5].text, "1.5");
}

// Each fault is refused with what was expected.
TEST(SweepAxis, MalformedRangesAreRefused) {
  EXPECT_NE(axis_refusal("hopper.semi_angle=15..40/5").find("give the range a unit"),
            std::string::npos);
  EXPECT_NE(axis_refusal("hopper.semi_angle=10,20,30").find("give the range a unit"),
            std::string::npos);
  EXPECT_NE(
      axis_refusal("hopper.outlet_width=1..2deg:3").find("is a length; \"deg\" measures angle"),
      std::string::npos);
  EXPECT_NE(axis_refusal("hopper.semi_angel=15..40deg/5deg").find("unknown key"),
            std::string::npos);
  EXPECT_NE(axis_refusal("hopper.semi_angle=40..15deg/5deg").find("empty"), std::string::npos);
  EXPECT_NE(axis_refusal("hopper.semi_angle=15..40deg/0deg").find("positive"), std::string::npos);
  EXPECT_NE(axis_refusal("hopper.semi_angle=15..40deg:1").find("from 2 to 100 000"),
            std::string::npos);
  EXPECT_NE(axis_refusal("hopper.semi_angle=15..40deg").find("a step or a count"),
            std::string::npos);
  EXPECT_NE(axis_refusal("hopper.semi_angle=15..40deg/1e-9deg").find("more than 100 000"),
            std::string::npos);
  EXPECT_NE(axis_refusal("hopper.outlet_width=0..1mm:3log").find("positive start"),
            std::string::npos);
  EXPECT_NE(axis_refusal("hopper.outlet_width=wide,narrow").find("takes numbers"),
            std::string::npos);
  EXPECT_NE(axis_refusal("hopper.shape=1,2").find("takes words"), std::string::npos);
  EXPECT_NE(axis_refusal("hopper.semi_angle").find("KEY=RANGE"), std::string::npos);
  EXPECT_NE(axis_refusal("hopper.fill_height=0.2,,0.5 m").find("empty item"), std::string::npos);
  EXPECT_NE(axis_refusal("hopper.fill_height=1..2 parsecs:3").find("is not a unit"),
            std::string::npos);
}

}  // namespace
}  // namespace feedflow
