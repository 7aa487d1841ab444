// `--sample lhs:N`: a Latin hypercube puts exactly one point in each of the N strata of every
// range, spreads a list's items evenly, and is the same for the same seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "designer/sweep/sweep_sample.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

// Each of the 50 strata of each range holds one point (log strata for a log range), values in
// the range, and the axes are not sampled in lock step.
TEST(SweepSample, OnePointPerStratumOfEveryRange) {
  const std::vector<SweepAxis> axes{parse_sweep_axis("hopper.semi_angle=15..40deg:2"),
                                    parse_sweep_axis("hopper.outlet_width=10..1000mm:3log")};
  const auto s = latin_hypercube(axes, {50, 7});
  ASSERT_EQ(s.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& span = *axes[k].span;
    std::vector<int> hits(50, 0);
    for (const auto& v : s[k].values) {
      const double f = span.log ? std::log(*v.si / span.low) / std::log(span.high / span.low)
                                : (*v.si - span.low) / (span.high - span.low);
      ASSERT_GE(f, -1e-6);
      ASSERT_LE(f, 1.0 + 1e-6);
      ++hits[std::min(49, static_cast<int>(f * 50 + 1e-9))];
    }
    for (int h : hits) EXPECT_EQ(h, 1);  // one per stratum (values rounded to 6 digits)
  }
  int same_order = 0;
  for (std::size_t p = 0; p + 1 < 50; ++p)
    same_order += (*s[0].values[p].si < *s[0].values[p + 1].si) ==
                  (*s[1].values[p].si < *s[1].values[p + 1].si);
  EXPECT_LT(same_order, 40);
}

// A list of two materials over 10 points: five each; the same seed gives the same sample and
// another seed another one.
TEST(SweepSample, ListsSpreadEvenlyAndSeedsRepeat) {
  const std::vector<SweepAxis> axes{parse_sweep_axis("material=pine,spruce"),
                                    parse_sweep_axis("hopper.semi_angle=15..40deg:2")};
  const auto a = latin_hypercube(axes, {10, 3}), b = latin_hypercube(axes, {10, 3}),
             c = latin_hypercube(axes, {10, 4});
  std::map<std::string, int> count;
  for (const auto& v : a[0].values) ++count[v.text];
  EXPECT_EQ(count["pine"], 5);
  EXPECT_EQ(count["spruce"], 5);
  for (std::size_t p = 0; p < 10; ++p) EXPECT_EQ(a[1].values[p].text, b[1].values[p].text);
  bool differs = false;
  for (std::size_t p = 0; p < 10; ++p)
    differs = differs || a[1].values[p].text != c[1].values[p].text;
  EXPECT_TRUE(differs);
}

// --sample takes lhs:N or lhs:N:SEED.
TEST(SweepSample, BadSamplesNameTheFlag) {
  EXPECT_EQ(parse_sample("lhs:200").points, 200u);
  EXPECT_EQ(parse_sample("lhs:20:9").seed, 9u);
  for (const char* bad : {"lhs", "lhs:1", "grid:20", "lhs:-3", "lhs:2:x"}) {
    try {
      parse_sample(bad);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "--sample");
    }
  }
}

}  // namespace
}  // namespace feedflow
