#include "models/numerics/mser_truncation.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace feedflow {
namespace {

// A start-up transient at the front and an emptying at the back: both ends are dropped, and
// with `front` only the back is kept (a drum's last batches are its steadiest, not an emptying).
TEST(MserTruncation, DropsTheTransientAndTheEmptyingOrTheFrontOnly) {
  // The drum at 20 rpm on 10 mm cells, 0.5 s batches (2026-12-06), then an emptying.
  const std::vector<double> drum{18, 63, 55, 51, 45, 39, 34, 35, 38, 32, 38, 35, 32, 34, 37, 32};
  std::vector<double> emptying = drum;
  emptying.insert(emptying.end(), {5, 1});
  const auto both = mser_truncation(emptying, 5);
  EXPECT_GE(both.first, 5u);   // the overshoot and its decay
  EXPECT_EQ(both.second, 2u);  // the emptying
  const auto front = mser_truncation(drum, 5, MserEnds::front);
  EXPECT_GE(front.first, 5u);
  EXPECT_LE(front.first, 7u);
  EXPECT_EQ(front.second, 0u);
}

// A steady series keeps (nearly) everything, and never fewer than the batches asked for.
TEST(MserTruncation, KeepsASteadySeriesAndTheLeastAskedFor) {
  const std::vector<double> steady{35, 34, 36, 35, 34, 36, 35, 34, 36, 35};
  EXPECT_LE(mser_truncation(steady, 5, MserEnds::front).first, 1u);
  const std::vector<double> falling{10, 9, 8, 7, 6, 5};
  const auto cut = mser_truncation(falling, 4, MserEnds::front);
  EXPECT_LE(cut.first, 2u);  // at least 4 of 6 kept
}

}  // namespace
}  // namespace feedflow
