// The results JSON keeps the documented shape and reads back to the same record.
#include <gtest/gtest.h>

#include "reports/results_json.hpp"
#include "reports/text_summary.hpp"

namespace feedflow {
namespace {

DesignRecord sample() {
  DesignRecord r;
  r.feedflow_version = "0.1.0";
  r.case_name = "pilot_hopper";
  r.kind = EquipmentKind::hopper;
  r.case_file = "cases/pilot_hopper.toml";
  r.description = "test";
  r.inputs = {{"hopper.semi_angle", 0.5235987755982988, "rad", "30 deg", ""},
              {"hopper.shape", std::string("wedge"), "", "wedge", ""},
              {"material.bulk.density", 290.0, "kg/m^3", "290 kg/m^3", "seed FEM deck"}};
  r.results = {{"critical_outlet_width", {0.0236, "m", 0.018, 0.031, "Jenike/Enstad", Rung::L0, ""}},
               {"flow_pattern", {std::string("mass"), "", std::nullopt, std::nullopt, "Arnold-McLean", Rung::L0, ""}}};
  r.verdict = {VerdictStatus::pass, {"outlet 60 mm >= 1.2 x 23.6 mm"}};
  r.wall_seconds = 0.0012;
  return r;
}

// Every documented top-level field is present with the documented type.
TEST(ResultsJson, HasTheDocumentedShape) {
  const auto j = to_json(sample());
  EXPECT_EQ(j.at("feedflow"), "0.1.0");
  for (const char* key : {"name", "kind", "file"}) EXPECT_TRUE(j.at("case").at(key).is_string());
  EXPECT_EQ(j.at("case").at("kind"), "hopper");
  EXPECT_DOUBLE_EQ(j.at("inputs").at("hopper").at("semi_angle").get<double>(), 0.5235987755982988);
  EXPECT_EQ(j.at("inputs").at("material").at("bulk").at("density"), 290.0);
  EXPECT_EQ(j.at("input_units").at("hopper.semi_angle"), "rad");
  const auto& q = j.at("results").at("critical_outlet_width");
  for (const char* key : {"value", "unit", "low", "high", "model", "rung"}) EXPECT_TRUE(q.contains(key)) << key;
  EXPECT_EQ(q.at("rung"), "L0");
  EXPECT_TRUE(j.at("results").at("flow_pattern").at("low").is_null());
  EXPECT_EQ(j.at("verdict").at("status"), "pass");
  EXPECT_TRUE(j.at("verdict").at("reasons").is_array());
  EXPECT_TRUE(j.at("timing").at("wall_s").is_number());
}

// A simulation's provenance (its run folders), the display units of results and findings, and
// its performance block (figures, phases in order) are written and read back as they were;
// results.txt shows the block with each phase's share of the wall time and "other" for the rest.
TEST(ResultsJson, SimulationProvenanceUnitsAndPerformanceRoundTrip) {
  DesignRecord a = sample();
  a.simulation_runs = {".", "../verify/run_6"};
  a.results[0].second.display_unit = "in";
  a.verdict.findings = {
      {VerdictStatus::pass, "mass_flow_rate", "5 t/h", 2.0, 1.5, 2.5, 1.3889, "kg/s", "t/h"}};
  a.performance = {{"DEM run",
                    10.0,
                    {{"throughput", "1.2e+06 particle-steps/s"}},
                    {{"pairs", 6.0}, {"walls", 2.5}}}};
  const DesignRecord b = design_record_from_json(nlohmann::ordered_json::parse(to_json(a).dump()));
  EXPECT_EQ(b.simulation_runs, a.simulation_runs);
  EXPECT_EQ(b.results[0].second.display_unit, "in");
  EXPECT_EQ(b.verdict.findings.at(0).display_unit, "t/h");
  ASSERT_EQ(b.performance.size(), 1u);
  EXPECT_EQ(b.performance[0].title, "DEM run");
  EXPECT_EQ(b.performance[0].wall_seconds, 10.0);
  EXPECT_EQ(b.performance[0].figures, a.performance[0].figures);
  EXPECT_EQ(b.performance[0].phases, a.performance[0].phases);
  const std::string text = text_summary(b);
  for (const char* line : {"Performance: DEM run", "1.2e+06 particle-steps/s", "phase: pairs",
                           "60 %", "phase: other", "15 %", "mass flow rate"})
    EXPECT_NE(text.find(line), std::string::npos) << line << "\n" << text;
  EXPECT_NE(text.find(">= 5 t/h"), std::string::npos)
      << "the margin table reads the finding's display unit\n"
      << text;
}

// Writing and reading back gives the same record, results in the same order, inputs shown as a
// person reads them ("30 deg", not "0.5235987755982988 rad": a report rendered again from the
// JSON shows what the first one showed).
TEST(ResultsJson, RoundTrips) {
  const DesignRecord a = sample();
  const DesignRecord b = design_record_from_json(nlohmann::ordered_json::parse(to_json(a).dump()));
  EXPECT_EQ(b.case_name, a.case_name);
  EXPECT_EQ(b.kind, a.kind);
  ASSERT_EQ(b.results.size(), 2u);
  EXPECT_EQ(b.results[0].first, "critical_outlet_width");
  EXPECT_DOUBLE_EQ(std::get<double>(b.results[0].second.value), 0.0236);
  EXPECT_DOUBLE_EQ(*b.results[0].second.high, 0.031);
  EXPECT_EQ(std::get<std::string>(b.results[1].second.value), "mass");
  EXPECT_FALSE(b.results[1].second.low.has_value());
  EXPECT_EQ(b.verdict.status, VerdictStatus::pass);
  ASSERT_EQ(b.inputs.size(), 3u);
  EXPECT_EQ(b.inputs[0].key, "hopper.semi_angle");
  EXPECT_EQ(b.inputs[0].si_unit, "rad");
  EXPECT_EQ(b.inputs[0].display, "30 deg");
  EXPECT_EQ(b.inputs[2].display, "290 kg/m^3");
}

// A malformed results file is refused naming the missing field.
TEST(ResultsJson, MalformedIsRefused) {
  auto j = to_json(sample());
  j["results"]["flow_pattern"].erase("rung");
  try {
    design_record_from_json(j);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("results.flow_pattern"), std::string::npos) << e.what();
  }
}

// The verdict's findings are written with their quantity, numbers and limit and read back; a
// note's status is "note"; a file written before findings existed reads with none.
TEST(ResultsJson, FindingsRoundTripAndOldFilesStillRead) {
  DesignRecord a = sample();
  a.verdict.findings = {{VerdictStatus::pass, "critical_outlet_width", "outlet 60 mm >= 1.2 x 31 mm", 0.0236, 0.018,
                         0.031, 0.05, "m"},
                        {std::nullopt, "arching", "arching: arches below 23.6 mm", std::nullopt, std::nullopt,
                         std::nullopt, std::nullopt, ""}};
  const auto j = to_json(a);
  const auto& f = j.at("verdict").at("findings");
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].at("quantity"), "critical_outlet_width");
  EXPECT_EQ(f[0].at("limit"), 0.05);
  EXPECT_EQ(f[1].at("status"), "note");
  EXPECT_TRUE(f[1].at("value").is_null());
  const DesignRecord b = design_record_from_json(nlohmann::ordered_json::parse(j.dump()));
  ASSERT_EQ(b.verdict.findings.size(), 2u);
  EXPECT_EQ(b.verdict.findings[0].status, VerdictStatus::pass);
  EXPECT_DOUBLE_EQ(*b.verdict.findings[0].high, 0.031);
  EXPECT_EQ(b.verdict.findings[0].unit, "m");
  EXPECT_FALSE(b.verdict.findings[1].status.has_value());
  EXPECT_FALSE(b.verdict.findings[1].limit.has_value());
  auto old = j;
  old["verdict"].erase("findings");
  EXPECT_TRUE(design_record_from_json(old).verdict.findings.empty());
  EXPECT_FALSE(to_json(sample()).at("verdict").contains("findings"));  // none made, none written
}

// The text summary shows inputs and results with their units, the band and the verdict.
TEST(TextSummary, ShowsUnitsBandAndVerdict) {
  const std::string t = text_summary(sample());
  EXPECT_NE(t.find("30 deg"), std::string::npos) << t;
  EXPECT_NE(t.find("0.0236 m"), std::string::npos) << t;
  EXPECT_NE(t.find("0.018 .. 0.031 m"), std::string::npos) << t;
  EXPECT_NE(t.find("Verdict: PASS"), std::string::npos) << t;
  EXPECT_NE(t.find("1.2 ms"), std::string::npos) << t;
  EXPECT_EQ(t.find("290 kg/m^3"), std::string::npos) << "material details belong to `feedflow materials`";
}

}  // namespace
}  // namespace feedflow
