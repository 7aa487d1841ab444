// The bench table shipped with the program (designer/bench/measured_bench): it parses, carries
// the pilot hopper's measured reference (Richardson on 10/5/2.5 mm, tests/benchmarks/RECORD.md),
// and the cheapest setting within a tolerance is the one the measurement shows.
#include <gtest/gtest.h>

#include <stdexcept>

#include "designer/bench/measured_bench.hpp"
#include "designer/calibrate/calibration_design.hpp"

namespace feedflow {
namespace {

// The hopper rate question: reference 5.787 +- 0.0069 kg/s, observed order 2.92, as recorded
// (re-measured on 2026-12-04 after the CEL staircase changes; it was 5.206 +- 0.439, order 0.763).
TEST(MeasuredBench, ShipsThePilotHoppersMeasuredReference) {
  const MeasuredBench& table = measured_bench();
  EXPECT_EQ(table.date, "2026-12-04");
  const MeasuredQuestion* q = table.find("hopper_discharge_rate_60mm");
  ASSERT_NE(q, nullptr);
  EXPECT_NEAR(*q->reference, 5.787, 1e-3);
  EXPECT_NEAR(*q->error_bar, 0.00687, 1e-5);
  EXPECT_NEAR(*q->order, 2.92, 1e-2);
  EXPECT_EQ(q->unit, "kg/s");
  EXPECT_GE(q->answers.size(), 10u);
}

// Within 10 % the cheapest measured answer is a reduced row calibrated against the CEL rung
// (Beverloo, 5.9 %, milliseconds); within 5 % another reduced row qualifies (Rose-Tanaka 0.3 %,
// Brown 0.04 %), not a CEL run (the 10 mm run is 5.5 % off, the 5 mm run takes minutes); the
// flow-pattern label is answered right by the reduced rung; a drum reference with an 85 % error
// bar judges no tolerance of 10 %.
TEST(MeasuredBench, CheapestWithinATolerance) {
  const MeasuredBench& table = measured_bench();
  const MeasuredQuestion& rate = *table.find("hopper_discharge_rate_60mm");
  const MeasuredAnswer* ten = cheapest_within(rate, 0.10);
  ASSERT_NE(ten, nullptr);
  EXPECT_EQ(ten->setting, "hopper.discharge=beverloo");
  EXPECT_LT(*ten->error, 0.10);
  const MeasuredAnswer* five = cheapest_within(rate, 0.05);
  ASSERT_NE(five, nullptr);
  EXPECT_EQ(five->rung, "L0");
  EXPECT_LT(*five->error, 0.05);
  const MeasuredAnswer* pattern = cheapest_within(*table.find("hopper_flow_pattern_60mm"), 0.0);
  ASSERT_NE(pattern, nullptr);
  EXPECT_EQ(pattern->rung, "L0");
  const MeasuredQuestion& drum = *table.find("drum_angle_10rpm");
  EXPECT_FALSE(reference_resolves(drum, 0.10));
  EXPECT_EQ(cheapest_within(drum, 0.10), nullptr);
}

// Two levels elsewhere extrapolate with the measured order only up to the first-order remap's
// formal order: the pilot's three levels converge with 2.92, which would shrink a 3-6 cell error
// bar 6.6-fold on geometries where the 3-to-6 change had either sign.
TEST(MeasuredBench, TwoLevelOrderIsCappedAtTheRemapsFormalOrder) {
  const MeasuredOrder m = measured_hopper_rate_order();
  EXPECT_EQ(m.order, kDonorCellFormalOrder);
  EXPECT_NE(m.source.find("formal order"), std::string::npos) << m.source;
  EXPECT_NE(m.source.find("2.92"), std::string::npos) << m.source;
}

// A damaged table is refused, not half read.
TEST(MeasuredBench, DamagedTableIsRefused) {
  EXPECT_THROW(parse_measured_bench("{\"questions\": []}"), std::invalid_argument);
  EXPECT_THROW(parse_measured_bench("not json"), std::invalid_argument);
}

}  // namespace
}  // namespace feedflow
