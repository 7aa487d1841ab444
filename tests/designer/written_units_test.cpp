// The unit each case value was written in: read from the text of the value, for plain values,
// value records and nested tables, and absent for bare (SI) numbers and for text that is no unit.
#include <gtest/gtest.h>

#include "designer/case/written_units.hpp"

namespace feedflow {
namespace {

// The unit part of a quantity's text, with or without a space; none for a bare number or a word.
TEST(WrittenUnits, UnitPartOfTheText) {
  EXPECT_EQ(unit_written("5 t/h"), "t/h");
  EXPECT_EQ(unit_written("32deg"), "deg");
  EXPECT_EQ(unit_written(" 290 kg/m^3 "), "kg/m^3");
  EXPECT_EQ(unit_written("0.5"), "");
  EXPECT_EQ(unit_written("wedge"), "");
  EXPECT_EQ(unit_written("5 furlongs"), "");  // not a unit the parser knows: shown by default
}

// Every table of a case, value records under their own key, numbers and labels left out.
TEST(WrittenUnits, EveryTableOfACase) {
  const toml::table root = toml::parse(R"(
    [hopper]
    shape = "wedge"
    outlet_width = "45 mm"
    fill_height = 0.68
    [design]
    required_throughput = { value = "5 t/h", source = "plant spec" }
    [material.bulk]
    density = "290 kg/m^3"
  )");
  const auto units = written_units(root);
  EXPECT_EQ(units.size(), 3u);
  EXPECT_EQ(units.at("hopper.outlet_width"), "mm");
  EXPECT_EQ(units.at("design.required_throughput"), "t/h");
  EXPECT_EQ(units.at("material.bulk.density"), "kg/m^3");
}

}  // namespace
}  // namespace feedflow
