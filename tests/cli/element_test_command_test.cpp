// `feedflow element-test`: output files with units, the summary, and exit code 2 on bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

class ElementTestCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_folder("feedflow_element_test", false);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The example: exit 0, a CSV with units in the header, a JSON summary whose numbers
// carry units and show the critical state being approached (q/p near M_c = 1.947 by 20 %).
TEST_F(ElementTestCommand, TriaxialWritesCsvAndSummary) {
  const auto r = run_feedflow(
      "element-test loblolly_pine --test triaxial --p0 2kPa --e0 0.8 --strain 20%", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("peak friction angle"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" deg"), std::string::npos) << r.out;
  const auto csv = slurp(dir_ / "out/element_test_triaxial/element_test.csv");
  EXPECT_EQ(csv.rfind("time [s],stage [-],eps_xx [-]", 0), 0u) << csv.substr(0, 200);
  EXPECT_NE(csv.find("sigma_zz [Pa]"), std::string::npos);
  EXPECT_GT(std::count(csv.begin(), csv.end(), '\n'), 200);
  const auto j = nlohmann::json::parse(slurp(dir_ / "out/element_test_triaxial/summary.json"));
  const auto& s = j.at("summary");
  EXPECT_EQ(s.at("peak_friction_angle").at("unit"), "deg");
  EXPECT_NEAR(s.at("critical_stress_ratio").at("value").get<double>(), 1.94672, 1e-4);
  EXPECT_NEAR(s.at("final_stress_ratio").at("value").get<double>(), 1.947, 0.15);
  EXPECT_GT(s.at("K0").at("value").get<double>(), 0.3);
  EXPECT_LT(s.at("K0").at("value").get<double>(), 0.5);
  EXPECT_EQ(s.at("initial_tangent_stiffness").at("unit"), "Pa");
  EXPECT_GT(s.at("initial_tangent_stiffness").at("value").get<double>(), 1e4);
}

// Every test name runs; --out chooses the folder; --json - prints only JSON.
TEST_F(ElementTestCommand, EveryTestRunsAndJsonToStdout) {
  for (const char* test : {"isotropic", "oedometric", "triaxial_extension", "simple_shear",
                           "cyclic_oedometric"}) {
    SCOPED_TRACE(test);
    const auto r = run_feedflow(std::string("element-test loblolly_pine --strain 5% --samples 20 --test ") +
                                    test + " --out o --json -",
                                dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("test"), test);
    EXPECT_TRUE(fs::exists(dir_ / "o/element_test.csv"));
  }
}

// Bad input: an unknown test, a length for --p0, e0 outside [e_d(p0), e_i(p0)], an unknown
// material: each a clear message on stderr and exit code 2, nothing written.
TEST_F(ElementTestCommand, BadInputExitsWithTwo) {
  const struct {
    const char* args;
    const char* message;
  } cases[] = {
      {"--test triaxal", "unknown element test 'triaxal'"},
      {"--p0 '2 mm'", "--p0"},
      {"--e0 1.0", "outside the admissible range"},
      {"--e0 0.2", "outside the admissible range"},
      {"--strain 20mm", "--strain"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = run_feedflow(std::string("element-test loblolly_pine ") + c.args, dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
  }
  EXPECT_EQ(run_feedflow("element-test no_such_material", dir_).exit_code, 2);
}

}  // namespace
