// Units: parsing quantities with units into SI, and rejecting what is not a quantity.
#include <gtest/gtest.h>

#include <numbers>

#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

constexpr double kPi = std::numbers::pi;

// Every unit the case files use converts to the right SI value and dimension.
TEST(QuantityParser, ConvertsEveryCaseFileUnitToSi) {
  struct Case { const char* text; double si; Dimension dimension; };
  const Case cases[] = {
      {"60 mm", 0.06, dim::length},
      {"0.68 m", 0.68, dim::length},
      {"35 cm", 0.35, dim::length},
      {"30 deg", 30 * kPi / 180, dim::angle},
      {"30\xC2\xB0", 30 * kPi / 180, dim::angle},
      {"1 rad", 1.0, dim::angle},
      {"20 rpm", 20 * 2 * kPi / 60, dim::angular_speed},
      {"2 rev/s", 4 * kPi, dim::angular_speed},
      {"290 kg/m^3", 290.0, dim::density},
      {"290 kg/m3", 290.0, dim::density},
      {"290 kg/m\xC2\xB3", 290.0, dim::density},
      {"0.29 g/cm^3", 290.0, dim::density},
      {"187.6 kPa", 187600.0, dim::pressure},
      {"1 MPa", 1e6, dim::pressure},
      {"1 us", 1e-6, dim::time},
      {"1 \xC2\xB5s", 1e-6, dim::time},
      {"2 s", 2.0, dim::time},
      {"5 min", 300.0, dim::time},
      {"50 %", 0.5, dim::dimensionless},
      {"50%", 0.5, dim::dimensionless},
      {"9.81 m/s^2", 9.81, dim::acceleration},
      {"36 t/h", 10.0, dim::mass_flow_rate},
      {"2 kg/s", 2.0, dim::mass_flow_rate},
      {"1.8e-5 Pa*s", 1.8e-5, dim::viscosity},
      {"1.8e-5 Pa.s", 1.8e-5, dim::viscosity},
      {"10 N", 10.0, dim::force},
      {"6e8 N/m^3", 6e8, dim::force / dim::volume},
      {"10 1/s", 10.0, dim::rate},
      {"32deg", 32 * kPi / 180, dim::angle},
      {"-5 mm", -0.005, dim::length},
      {"+5 mm", 0.005, dim::length},
      {"  0.5  ", 0.5, dim::dimensionless},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    const Quantity q = parse_quantity(c.text);
    EXPECT_NEAR(q.si, c.si, 1e-12 * std::max(1.0, std::abs(c.si)));
    EXPECT_EQ(q.dimension, c.dimension);
  }
}

// Text that is not a quantity is refused with a message, never turned into a number.
TEST(QuantityParser, RejectsMalformedText) {
  for (const char* bad : {"", "mm", "abc", "30 furlongs", "30 mm/", "30 m^", "nan", "inf m",
                          "30 mm mm2x", "1e999 m", "30 m^0", "--3 m"}) {
    SCOPED_TRACE(bad);
    EXPECT_THROW(parse_quantity(bad), UnitError);
  }
}

// A length given for an angle is a dimension mismatch; the message names both dimensions.
TEST(QuantityParser, DimensionMismatchNamesBoth) {
  try {
    parse_quantity_as("30 mm", dim::angle);
    FAIL() << "no error";
  } catch (const UnitError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("angle"), std::string::npos) << m;
    EXPECT_NE(m.find("length"), std::string::npos) << m;
  }
  EXPECT_THROW(parse_quantity_as("20 Hz", dim::angular_speed), UnitError);
  EXPECT_THROW(parse_quantity_as("50 %", dim::length), UnitError);
}

// A bare number is SI for any dimension (case-file convention) unless the caller refuses it.
TEST(QuantityParser, BareNumbersAreSi) {
  EXPECT_DOUBLE_EQ(parse_quantity_as("0.5", dim::length), 0.5);
  EXPECT_THROW(parse_quantity_as("0.5", dim::length, false), UnitError);
}

// Formatting converts back from SI and always prints the unit.
TEST(QuantityFormat, PrintsInTheRequestedUnit) {
  EXPECT_EQ(format_quantity(0.06, "mm"), "60 mm");
  EXPECT_EQ(format_quantity(30 * kPi / 180, "deg"), "30 deg");
  EXPECT_EQ(format_quantity(20 * 2 * kPi / 60, "rpm"), "20 rpm");
  EXPECT_EQ(format_quantity(187600, "kPa"), "187.6 kPa");
  EXPECT_EQ(format_quantity(0.5, "%"), "50%");
  EXPECT_EQ(format_quantity(6e8, "N/m^3"), "6e8 N/m^3");
  EXPECT_EQ(format_quantity(1e-7, "m^2"), "1e-7 m^2");
  EXPECT_EQ(format_number(0.3), "0.3");
}

// SI unit names and dimension names used in messages and in the results JSON.
TEST(Dimension, NamesAndSiUnits) {
  EXPECT_EQ(si_unit(dim::density), "kg/m^3");
  EXPECT_EQ(si_unit(dim::angle), "rad");
  EXPECT_EQ(si_unit(dim::force / dim::volume), "kg/m^2*s^2");
  EXPECT_EQ(dimension_name(dim::angular_speed), "rotation speed");
}

}  // namespace
}  // namespace feedflow
