// The margin table (reports/margin_table): a ceiling and a floor are told apart by the judges'
// rules, the margin is the band's near edge against the limit, and the worst status governs
// (then the least margin); notes and findings without a limit are not rows.
#include <gtest/gtest.h>

#include <string>

#include "reports/margin_table.hpp"

namespace feedflow {
namespace {

Finding judged(VerdictStatus s, std::string q, double value, double low, double high, double limit, std::string unit) {
  return Finding{s, std::move(q), "", value, low, high, limit, std::move(unit)};
}

// B_c 30.6 mm (20.5-42.2) under an allowed 37.5 mm is a marginal ceiling, 12.5 % short at the
// band's top; a throughput of 4.8 kg/s (3.7-6.1) over 3 kg/s a passing floor, 22 % clear at
// the band's bottom; the marginal one governs.
TEST(MarginTable, CeilingsFloorsAndTheGoverningCheck) {
  Verdict v;
  v.findings = {judged(VerdictStatus::marginal, "critical_outlet_width", 0.0306, 0.0205, 0.0422, 0.0375, "m"),
                judged(VerdictStatus::pass, "mass_flow_rate", 4.8, 3.66, 6.1, 3.0, "kg/s"),
                Finding{std::nullopt, "arching", "arching: a note", {}, {}, {}, {}, ""}};
  const auto rows = margin_table(v);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].requirement, "<= 37.5 mm");
  EXPECT_NEAR(rows[0].relative_margin, (0.0375 - 0.0422) / 0.0375, 1e-12);
  EXPECT_TRUE(rows[0].governing);
  EXPECT_EQ(rows[1].requirement, ">= 3 kg/s");
  EXPECT_NEAR(rows[1].relative_margin, (3.66 - 3.0) / 3.0, 1e-12);
  EXPECT_FALSE(rows[1].governing);
}

// A failed floor (2.58 kg/s against 3) outranks a marginal ceiling; among passes the least
// margin governs.
TEST(MarginTable, WorstStatusThenLeastMarginGoverns) {
  Verdict v;
  v.findings = {judged(VerdictStatus::marginal, "critical_outlet_width", 0.0306, 0.0205, 0.0422, 0.0375, "m"),
                judged(VerdictStatus::fail, "mass_flow_rate", 2.58, 1.1, 4.0, 3.0, "kg/s")};
  auto rows = margin_table(v);
  EXPECT_EQ(rows[1].requirement, ">= 3 kg/s");
  EXPECT_TRUE(rows[1].governing);
  v.findings = {judged(VerdictStatus::pass, "mass_flow_rate", 4.8, 3.66, 6.1, 3.0, "kg/s"),
                judged(VerdictStatus::pass, "mechanical_arching_width", 0.0143, 0.0054, 0.0143, 0.045, "m")};
  rows = margin_table(v);
  EXPECT_TRUE(rows[0].governing);  // 22 % against 68 %
  EXPECT_FALSE(rows[1].governing);
}

}  // namespace
}  // namespace feedflow
