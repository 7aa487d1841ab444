// `feedflow simulate --solver cel` on a conical hopper (issue 22), as a user runs it: the
// shipped pilot cone (cases/conical_hopper.toml: 60 mm orifice, 20 deg cone, 0.3 m bin) on the
// axisymmetric (r, z) grid at the default 10 mm cells.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <gsl/gsl_fit.h>
#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

class SimulateConeCel : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_folder("feedflow_simcone_cel", true);
    fs::copy_file(fs::path(FEEDFLOW_SOURCE_DIR) / "cases/conical_hopper.toml", dir_ / "cone.toml");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The cone discharges on rung L2 as a user runs it: the run does not stop before 2 s after the
// opening (the rate still climbs in the first second), the mass balanced to round-off. Its rate
// is per radian x 2 pi (no per-metre rate of a slot) and agrees within 10 % with the run at 5 mm
// cells (0.505 kg/s over 3 s; 0.483 kg/s at 10 mm). Against Beverloo for a circular orifice,
// W = C rho_b sqrt(g) D^2.5 (a continuum has no grain size: k d = 0), that is C = 0.60 at
// rho_b = 290 kg/m^3 (0.63 at 5 mm), in the published 0.55-0.65 (Beverloo, Leniger & van de
// Velde 1961; Nedderman 1992, ch. 10). A 20 deg cone with 8.5 deg walls is in mass flow (the
// Arnold-McLean limit is 39.6 deg): the material at the wall moves.
TEST_F(SimulateConeCel, PilotConeDischargesOnTheAxisymmetricGrid) {
  const auto r = run_feedflow("simulate cone.toml --solver cel --out sim", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("scene: conical hopper, axisymmetric (r, z) about its axis"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("outlet: bottom box face from r = 0 m to 0.03 m"), std::string::npos) << r.out;
  const auto json = nlohmann::json::parse(slurp(dir_ / "sim/results.json"));
  const auto& results = json.at("results");
  const auto& q = results.at("mass_flow_rate");
  EXPECT_EQ(q.at("rung"), "L2");
  EXPECT_NE(q.at("model").get<std::string>().find("CEL-FEM axisymmetric"), std::string::npos);
  const double rate = q.at("value").get<double>();
  EXPECT_LT(q.at("low").get<double>(), rate);
  EXPECT_GT(q.at("high").get<double>(), rate);
  std::printf("q_m %.4f kg/s, Beverloo C %.3f\n", rate, rate / (290.0 * std::sqrt(9.81) * std::pow(0.06, 2.5)));
  EXPECT_NEAR(rate / 0.505, 1.0, 0.10);
  EXPECT_FALSE(results.contains("mass_flow_rate_per_metre"));
  EXPECT_TRUE(results.contains("flow_pattern"));
  EXPECT_GE(results.at("simulated_time_after_opening").at("value").get<double>(), 2.0);
  EXPECT_EQ(results.at("arching").at("value"), "flowing");
  EXPECT_LT(std::abs(results.at("mass_balance_error").at("value").get<double>()), 1e-12);
  // The staircase's excess is reported, as measured (14 % of the grid's mass at the end).
  const double overfilled = results.at("overfilled_mass_share").at("value").get<double>();
  EXPECT_EQ(results.at("overfilled_mass_share").at("unit"), "%");
  EXPECT_GT(overfilled, 5.0);
  EXPECT_LT(overfilled, 25.0);
  EXPECT_EQ(results.at("flow_pattern").at("value"), "mass");
  EXPECT_GT(results.at("wall_to_centre_speed_ratio").at("value").get<double>(), 0.3);
  bool caveat = false;  // the flow pattern's non-convergence on the axisymmetric grid is said
  for (const auto& a : json.at("assumptions"))
    caveat = caveat || a.get<std::string>().find("The flow pattern on this grid does not converge") != std::string::npos;
  EXPECT_TRUE(caveat);
}

// The mass/funnel boundary on the axisymmetric grid at the default 10 mm cells: the pilot cone
// (8.5 deg walls, filled 0.42 m above the outlet) flows in mass flow at 30 deg and in funnel flow
// at 45 deg, on either side of the Arnold-McLean conical limit the reduced rung computes (39.6
// deg). Measured wall/centre speed ratios: 0.69 at 20, 0.39 at 30, 0.14 at 40, 0.006 at 45 deg.
// This holds on 10 mm cells only: the wall zone slows as the cells shrink (20 deg: 0.71 at 5 mm,
// 0.38 at 2.5 mm; 30 deg: 0.23, 0.079, and funnel flow at 1.25 mm with 0.019; 40 deg: 0.019,
// 0.007; with cut cells at the wall too: 30 deg 0.148, 0.278, 0.081 at 10, 5, 2.5 mm and funnel
// flow at 1.25 mm with 0.084, a 30 and a 38.75 mm band on 2.5 and 1.25 mm cells), which is
// why design --verify does not use the pattern. LONG (half a minute; the pilot cone's discharge
// above is its fast counterpart).
TEST_F(SimulateConeCel, LONG_MassAndFunnelFlowOnEitherSideOfTheConicalLimit) {
  for (const auto& [angle, pattern] : {std::pair{30.0, "mass"}, std::pair{45.0, "funnel"}}) {
    const double fill = 0.42 + 0.03 / std::tan(angle * std::numbers::pi / 180.0);
    const auto r = run_feedflow("simulate cone.toml --solver cel --time 2.5s --set hopper.semi_angle=" +
                                    std::to_string(angle) + "deg --set hopper.fill_height=" +
                                    std::to_string(fill) + "m --out sim" + std::to_string(int(angle)),
                                dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto json = nlohmann::json::parse(slurp(dir_ / ("sim" + std::to_string(int(angle))) / "results.json"));
    EXPECT_EQ(json.at("results").at("flow_pattern").at("value"), pattern) << angle << " deg";
    EXPECT_EQ(json.at("results").at("flow_pattern_reduced_model").at("value"), angle < 39.6 ? "mass" : "funnel");
  }
}

// Beverloo's D^2.5 on the axisymmetric grid (5 mm cells, the pilot cone filled 0.75 m above the
// apex, 2.5 s after the opening): W = C rho_b sqrt(g) D^2.5 with k d = 0 (a continuum has no
// grain) gives C within 0.01 of the published 0.55-0.65 at each of four diameters (Beverloo,
// Leniger & van de Velde 1961; Nedderman 1992, ch. 10), and log W against log D has the slope 2.5.
// Measured: C = 0.612, 0.621, 0.635, 0.612 at 40, 60, 80, 100 mm, slope 2.51 (12 min on one
// thread per run, two at a time; with the quarter-cell wall rule before 0.597, 0.638, 0.651, 0.648).
TEST_F(SimulateConeCel, LONG_BeverlooOverFourDiameters) {
  std::vector<double> log_d, log_w;
  for (int d : {40, 60, 80, 100}) {
    const std::string out = "bev" + std::to_string(d);
    const auto r = run_feedflow("simulate cone.toml --solver cel --time 2.5s --set cel.cell_size=5mm --set "
                                "hopper.outlet_width=" + std::to_string(d) + "mm --set hopper.fill_height=0.75m --out " + out,
                                dir_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto json = nlohmann::json::parse(slurp(dir_ / out / "results.json"));
    const double w = json.at("results").at("mass_flow_rate").at("value").get<double>();
    const double c = w / (290.0 * std::sqrt(9.81) * std::pow(d * 1e-3, 2.5));
    std::printf("D %d mm: q_m %.4f kg/s, C %.3f\n", d, w, c);
    EXPECT_GT(c, 0.55) << d;
    EXPECT_LT(c, 0.66) << d;
    log_d.push_back(std::log(d * 1e-3));
    log_w.push_back(std::log(w));
  }
  double intercept = 0.0, slope = 0.0, c00 = 0.0, c01 = 0.0, c11 = 0.0, sum_sq = 0.0;
  gsl_fit_linear(log_d.data(), 1, log_w.data(), 1, log_d.size(), &intercept, &slope, &c00, &c01, &c11, &sum_sq);
  EXPECT_NEAR(slope, 2.5, 0.15);
}

// The full-width plane section is for wedges, and the void-first mixed cells do not settle a
// cone's fill: asked of a cone, each is refused naming its key, and nothing is written.
TEST_F(SimulateConeCel, WedgeOnlySettingsAreRefusedForACone) {
  for (const std::string set : {"cel.hopper_section=full", "cel.mixed_cells=void_first"}) {
    const auto r = run_feedflow("simulate cone.toml --solver cel --set " + set + " --out sim", dir_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(set.substr(0, set.find('='))), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "sim"));
  }
}

}  // namespace
