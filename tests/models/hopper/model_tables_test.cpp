// The model tables of the hopper and the chute: each row named once, the default first, every
// row evaluating what its summary says (the same numbers as the model functions it wraps).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "models/chute/deposit_models.hpp"
#include "models/chute/stopping_thickness_models.hpp"
#include "models/hopper/bulk_density_models.hpp"
#include "models/hopper/critical_outlet_models.hpp"
#include "models/hopper/discharge_models.hpp"
#include "models/hopper/enstad_flow_factor.hpp"
#include "models/hopper/flow_factor_models.hpp"
#include "models/hopper/flow_pattern.hpp"
#include "models/hopper/minimum_energy_discharge.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

template <class Row>
void expect_well_formed(const ModelTable<Row>& table) {
  SCOPED_TRACE(std::string(table.key));
  std::set<std::string_view> names;
  for (const auto& row : table.rows) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name;  // each name once
    EXPECT_FALSE(row.summary.empty()) << row.name;
    EXPECT_NE(row.evaluate, nullptr) << row.name;
    EXPECT_EQ(&table.at(row.name), &row);
  }
  EXPECT_EQ(&table.default_row(), &table.rows.front());
  EXPECT_EQ(table.find("no such model"), nullptr);
  EXPECT_THROW(table.at("no such model"), std::out_of_range);
  EXPECT_EQ(table.listing().entries.size(), table.rows.size());
}

// Every table is well formed and its default is the model the design check used before tables.
TEST(ModelTables, WellFormedWithTheirDefaults) {
  expect_well_formed(flow_factor_models());
  expect_well_formed(critical_outlet_models());
  expect_well_formed(discharge_models());
  expect_well_formed(hopper_density_models());
  expect_well_formed(stopping_thickness_models());
  expect_well_formed(chute_deposit_models());
  EXPECT_EQ(flow_factor_models().default_row().name, "enstad");
  EXPECT_EQ(critical_outlet_models().default_row().name, "envelope");
  EXPECT_EQ(discharge_models().default_row().name, "johanson");
  EXPECT_EQ(hopper_density_models().default_row().name, "compressible");
  EXPECT_EQ(stopping_thickness_models().default_row().name, "pouliquen");
  EXPECT_EQ(chute_deposit_models().default_row().name, "l1");
}

// The flow-factor rows: enstad is the closed form, rsf Jenike's field within the tolerance of
// reduced_models.md for plane hoppers (-7 % .. +10.5 %).
TEST(ModelTables, FlowFactorRows) {
  const auto& t = flow_factor_models();
  const double enstad = t.at("enstad").evaluate(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree);
  EXPECT_DOUBLE_EQ(enstad, enstad_flow_factor(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree));
  EXPECT_NEAR(t.at("rsf").evaluate(FlowGeometry::plane, 30 * kDegree, 50 * kDegree, 8.5 * kDegree) / enstad, 1.0, 0.105);
}

// The critical-outlet rows: the envelope is the larger estimate, and a cone (no static arch)
// falls back to Jenike in every row.
TEST(ModelTables, CriticalOutletRows) {
  CriticalOutlet jenike{ArchingOutcome::critical_width, 0.030, 1.0, 0, 0, 290, false, "Jenike"};
  CriticalOutlet arch = jenike;
  arch.width = 0.035;
  arch.model = "static arch";
  const auto& t = critical_outlet_models();
  EXPECT_DOUBLE_EQ(t.at("envelope").evaluate(jenike, arch).width, 0.035);
  EXPECT_DOUBLE_EQ(t.at("jenike").evaluate(jenike, arch).width, 0.030);
  EXPECT_DOUBLE_EQ(t.at("static_arch").evaluate(jenike, arch).width, 0.035);
  for (const auto& row : t.rows) EXPECT_DOUBLE_EQ(row.evaluate(jenike, std::nullopt).width, 0.030) << row.name;
}

// The discharge rows give the model functions' rates; Brown-Richards applies to wedges only.
TEST(ModelTables, DischargeRows) {
  const auto rho = BulkDensity::constant(290);
  const auto johanson = johanson_discharge(FlowGeometry::plane, 30 * kDegree, 0.06, 1.315, FlowFunction::cohesionless(), rho);
  const DischargeInputs wedge{FlowGeometry::plane, 30 * kDegree, 0.06, johanson, 0.82e-3};
  const auto& t = discharge_models();
  EXPECT_DOUBLE_EQ(t.at("johanson").published(wedge)->rate, johanson.rate);
  EXPECT_DOUBLE_EQ(t.at("beverloo").published(wedge)->rate, beverloo_slot_rate_per_metre(290, 0.06, 0.82e-3));
  EXPECT_DOUBLE_EQ(t.at("brown").published(wedge)->rate, brown_richards_rate_per_metre(290, 0.06, 30 * kDegree));
  const DischargeInputs cone{FlowGeometry::conical, 30 * kDegree, 0.06, johanson, 0.82e-3};
  EXPECT_FALSE(t.at("brown").published(cone).has_value());
  EXPECT_DOUBLE_EQ(t.at("beverloo").published(cone)->rate, beverloo_circular_rate(290, 0.06, 0.82e-3));
}

// The rose_tanaka row is Beverloo times Rose & Tanaka's factor with the stagnant zone at the
// flow-pattern boundary: faster in mass flow, Beverloo itself past the mass-flow limit.
TEST(ModelTables, RoseTanakaRow) {
  const auto rho = BulkDensity::constant(290);
  const auto johanson = johanson_discharge(FlowGeometry::conical, 20 * kDegree, 0.1, 1.5, FlowFunction::cohesionless(), rho);
  const double delta = 50 * kDegree, phi_w = 15 * kDegree;
  const double limit = mass_flow_limit(FlowGeometry::conical, delta, phi_w).nominal;
  const auto& t = discharge_models();
  const DischargeInputs steep{FlowGeometry::conical, 20 * kDegree, 0.1, johanson, 1e-3, delta, phi_w};
  const double beverloo = t.at("beverloo").published(steep)->rate;
  EXPECT_NEAR(t.at("rose_tanaka").published(steep)->rate / beverloo,
              std::pow(std::tan(20 * kDegree) * std::tan(90 * kDegree - limit), -0.35), 1e-12);
  EXPECT_GT(t.at("rose_tanaka").published(steep)->rate, beverloo);
  const DischargeInputs funnel{FlowGeometry::conical, limit + 5 * kDegree, 0.1, johanson, 1e-3, delta, phi_w};
  EXPECT_DOUBLE_EQ(t.at("rose_tanaka").published(funnel)->rate, t.at("beverloo").published(funnel)->rate);
  EXPECT_FALSE(t.at("rose_tanaka").spans_band);  // the released rate band is unchanged
}

}  // namespace
}  // namespace feedflow
