// Bulk compressibility from the Bauer compression law of the hypoplastic parameters.
#include <gtest/gtest.h>

#include "models/material/bulk_compressibility.hpp"

namespace feedflow {
namespace {

HypoplasticParameters table1() {  // seed Table 1
  return {47.3 * 3.14159265358979 / 180, 187.6e3, 0.30, 0.50, 1.06, 1.38, 0.3, 1.0};
}

// reduced_models.md section 0: e_c = 0.99, 0.92, 0.79, 0.60 at p = 0.01, 0.1, 1, 10 kPa.
TEST(BulkCompressibility, CriticalVoidRatioMatchesPublishedValues) {
  const auto hp = table1();
  EXPECT_NEAR(limit_void_ratios(hp, 10.0).e_c, 0.99, 0.005);
  EXPECT_NEAR(limit_void_ratios(hp, 100.0).e_c, 0.92, 0.005);
  EXPECT_NEAR(limit_void_ratios(hp, 1e3).e_c, 0.79, 0.005);
  EXPECT_NEAR(limit_void_ratios(hp, 1e4).e_c, 0.60, 0.005);
  EXPECT_DOUBLE_EQ(limit_void_ratios(hp, 0.0).e_i, 1.38);  // zero pressure: the e_x0 values
}

// Anchored at the 182 kg/m^3 loose density, the densest state gives the FEM deck's 290 kg/m^3
// (reduced_models.md section 0: 182, 210 and 289 kg/m^3 at e_i0, e_c0, e_d0).
TEST(BulkCompressibility, PineDensitiesSpanLooseToFemDeck) {
  Material pine;
  pine.bulk.density = 290.0;
  pine.bulk.loose_density = 182.0;
  pine.hypoplastic = table1();
  const auto c = BulkCompressibility::of(pine);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->solid_density(), 433.2, 0.1);
  EXPECT_NEAR(c->loosest_density(0.0), 182.0, 1e-9);
  EXPECT_NEAR(c->critical_density(0.0), 210.0, 0.5);
  EXPECT_NEAR(c->densest_density(0.0), 289.0, 0.5);
  // Compression: density rises monotonically with pressure on every line.
  EXPECT_LT(c->critical_density(100.0), c->critical_density(1e3));
  EXPECT_LT(c->critical_density(1e3), c->critical_density(1e4));
}

// A material without hypoplastic parameters has no compressibility model, and says so.
TEST(BulkCompressibility, AbsentWithoutHypoplasticParameters) {
  Material m;
  m.bulk.density = 300.0;
  EXPECT_FALSE(BulkCompressibility::of(m).has_value());
  EXPECT_THROW(limit_void_ratios(table1(), -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace feedflow

