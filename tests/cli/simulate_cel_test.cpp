// `feedflow simulate --solver cel` end to end: results JSON (rung L2), time series, HDF5 fields
// with their XDMF sidecar, a checkpoint, and a restart that continues the run bit-identically.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "models/units/quantity_format.hpp"
#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

class SimulateCel : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratch_folder("feedflow_cel_cli", true);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

const std::string kHopper =
    "simulate cases/pilot_hopper.toml --solver cel --set cel.cell_size=20mm "
    "--set hopper.outlet_width=120mm ";

double result_value(const nlohmann::json& j, const std::string& name) {
  if (!j.at("results").contains(name)) {
    ADD_FAILURE() << "no result " << name;
    return 0.0;
  }
  return j.at("results").at(name).at("value").get<double>();
}

// A nearly frictionless wedge (phi_w 2.5 deg) settles and discharges at the default Courant
// number 0.8 with its mass conserved. Before the corner contact its outlet lip slid on the closed
// gate, the cell beside it was crushed (void ratio towards 0, MPa) and the step-collapse guard
// stopped the run with exit 4 at t = 1.75 s of the settling.
TEST_F(SimulateCel, SmoothWedgeRunsAtTheDefaultCourantNumber) {
  const auto smooth = run_feedflow(
      kHopper + "--time 0.05s --set hopper.wall_friction_angle=2.5deg --out smooth", dir_);
  ASSERT_EQ(smooth.exit_code, 0) << smooth.err;
  const auto j = nlohmann::json::parse(slurp(dir_ / "smooth/results.json"));
  EXPECT_LT(std::abs(result_value(j, "mass_balance_error")), 1e-12);
}

// The pilot hopper (120 mm outlet, 20 mm cells: 3 across the half outlet) for 0.4 s after the opening: exit 0, rung L2
// results with q_m (a steady window needs five 50 ms batches after the first discharge, as on
// every rung) and the reduced model's q_m beside it, mass bookkeeping to round-off, the plan and
// the performance block printed, the time series, fields and sidecar written; a run of 0.2 s
// continued from its checkpoint to 0.4 s gives the same discharged mass to the last bit and the
// same time series.
TEST_F(SimulateCel, HopperRunsAndRestartsBitIdentically) {
  const auto straight = run_feedflow(kHopper + "--time 0.4s --out straight", dir_);
  ASSERT_EQ(straight.exit_code, 0) << straight.err;
  EXPECT_NE(straight.out.find("CEL-FEM plan"), std::string::npos);
  EXPECT_NE(straight.out.find("cell updates/s"), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(dir_ / "straight/results.json"));
  EXPECT_EQ(j.at("results").at("mass_flow_rate").at("rung"), "L2");
  EXPECT_GT(result_value(j, "mass_flow_rate"), 0.0);
  EXPECT_GT(result_value(j, "mass_flow_rate_reduced_model"), 0.0);
  EXPECT_LT(std::abs(result_value(j, "mass_balance_error")), 1e-12);
  EXPECT_NE(slurp(dir_ / "straight/timeseries.csv").find("discharged_mass [kg]"), std::string::npos);
  EXPECT_NE(slurp(dir_ / "straight/fields.xdmf").find("2DCoRectMesh"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "straight/fields.h5"));

  const auto first = run_feedflow(kHopper + "--time 0.2s --out first", dir_);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const auto resumed =
      run_feedflow(kHopper + "--time 0.4s --restart first/checkpoint.h5 --out resumed", dir_);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("restarted from"), std::string::npos);
  const auto k = nlohmann::json::parse(slurp(dir_ / "resumed/results.json"));
  EXPECT_EQ(result_value(k, "discharged_mass"), result_value(j, "discharged_mass"));
  EXPECT_GT(result_value(k, "discharged_mass"), 0.0);
  EXPECT_EQ(slurp(dir_ / "resumed/timeseries.csv"), slurp(dir_ / "straight/timeseries.csv"));
}

// A checkpoint of another grid is refused as bad input (exit 2) naming --restart and the
// setting that differs, with both values.
TEST_F(SimulateCel, RestartFromAnotherGridIsRefused) {
  const auto first = run_feedflow(kHopper + "--time 0.01s --out first", dir_);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const auto r = run_feedflow(kHopper + "--set cel.cell_size=15mm --time 0.01s --restart first/checkpoint.h5 --out other",
                              dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--restart"), std::string::npos);
  EXPECT_NE(r.err.find("cel.cell_size"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("20 mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("15 mm"), std::string::npos) << r.err;
}

// Cells too coarse for the outlet are refused before any work (exit 2, nothing written), naming
// cel.cell_size, the cells across the half outlet and the largest cell that resolves it: the
// bench measured the 60 mm pilot hopper read "arched" on 20 mm cells though it flows. A cell
// larger than the whole hopper (10 m) is refused the same way, not answered with NaN.
TEST_F(SimulateCel, CellsTooCoarseForTheOutletAreRefused) {
  const auto r = run_feedflow("simulate cases/pilot_hopper.toml --solver cel --set cel.cell_size=20mm --out o", dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cel.cell_size: 20 mm puts 1.5 cells across the half outlet (30 mm)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("use at most 10 mm"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "o"));
  const auto huge = run_feedflow("simulate cases/pilot_hopper.toml --solver cel --set cel.cell_size=10m --out o", dir_);
  EXPECT_EQ(huge.exit_code, 2);
  EXPECT_NE(huge.err.find("cel.cell_size"), std::string::npos) << huge.err;
  EXPECT_FALSE(fs::exists(dir_ / "o"));
}

// [cel] remap_order, material_flux and mixed_cells reach the solver: the plan and the result's
// model name say second order and PLIC, the plan says void first; an unknown order is refused
// as bad input (exit 2) naming the key.
TEST_F(SimulateCel, RemapOptionsReachThePlanAndTheResults) {
  const auto r = run_feedflow(kHopper + "--set cel.remap_order=second --set cel.material_flux=plic "
                                        "--set cel.mixed_cells=void_first --time 0.02s --out plic",
                              dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("mixed cells: void first"), std::string::npos);
  EXPECT_NE(r.out.find("remap: second-order (van Leer MUSCL: stress void ratio density "
                       "momentum) state, "
                       "PLIC (Youngs) material flux"), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(dir_ / "plic/results.json"));
  EXPECT_NE(j.at("results").at("discharged_mass").at("model").get<std::string>().find(
                "second-order, PLIC, void-first mixed cells remap"), std::string::npos);
  const auto bad = run_feedflow(kHopper + "--set cel.remap_order=third --time 0.01s --out bad", dir_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("cel.remap_order"), std::string::npos);
}

// [cel] hopper_section reaches the scene: "full" puts the full-width section in the plan, the
// discharged mass row's model and the first assumption, without the key the same say half slice; an unknown
// section is refused as bad input (exit 2) naming the key.
TEST_F(SimulateCel, HopperSectionReachesThePlanAndTheResults) {
  const auto full = run_feedflow(kHopper + "--set cel.hopper_section=full --time 0.02s --out full", dir_);
  ASSERT_EQ(full.exit_code, 0) << full.err;
  EXPECT_NE(full.out.find("scene: wedge hopper, plane-strain full-width section (both walls, "
                          "centre line x = 0.3 m)"), std::string::npos);
  const auto j = nlohmann::json::parse(slurp(dir_ / "full/results.json"));
  EXPECT_NE(j.at("results").at("discharged_mass").at("model").get<std::string>().find("full-width section"),
            std::string::npos);
  EXPECT_NE(j.dump().find("Plane strain full-width section, both walls ([cel] hopper_section = "
                          "full)"), std::string::npos);
  EXPECT_EQ(j.dump().find("half slice"), std::string::npos);
  const auto half = run_feedflow(kHopper + "--time 0.02s --out half", dir_);
  ASSERT_EQ(half.exit_code, 0) << half.err;
  EXPECT_NE(half.out.find("plane-strain half slice"), std::string::npos);
  const auto k = nlohmann::json::parse(slurp(dir_ / "half/results.json"));
  EXPECT_NE(k.at("results").at("discharged_mass").at("model").get<std::string>().find("half slice"),
            std::string::npos);
  EXPECT_EQ(k.dump().find("full-width"), std::string::npos);
  const auto bad = run_feedflow(kHopper + "--set cel.hopper_section=third --time 0.01s --out bad", dir_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("cel.hopper_section"), std::string::npos);
}

// The CEL drum reports its regime from the measured bed state, as the particle rung does: at
// 50 rpm on 10 mm cells over 3 s the bed cascades (the seed's label at 50 rpm; measured: its mean
// surface bends by 34.3 % of R against the 25 % threshold), the angle's interval is a result, and
// the time series carries the bed state and the surface's profile, all finite.
TEST_F(SimulateCel, DrumReportsItsRegimeFromTheBedState) {
  const auto r = run_feedflow(
      "simulate cases/rotating_drum_20rpm.toml --solver cel --set cel.cell_size=10mm "
      "--set drum.speed=50rpm --time 3s --out drum",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(dir_ / "drum/results.json"));
  const auto& regime = j.at("results").at("regime");
  EXPECT_EQ(regime.at("value"), "cascading");
  EXPECT_EQ(regime.at("rung"), "L2");
  EXPECT_NE(regime.at("model").get<std::string>().find("measured bed state"), std::string::npos);
  // the angle's mean carries its 95 % interval as a result of its own (measured: +-7.5 deg over
  // 4 batches), the one its model names, narrower than the 2 SD band of the sampled angle
  const auto& angle = j.at("results").at("dynamic_angle_of_repose");
  const auto& interval = j.at("results").at("dynamic_angle_of_repose_interval");
  EXPECT_EQ(interval.at("unit"), "deg");
  EXPECT_GT(interval.at("value").get<double>(), 0.0);
  EXPECT_LT(interval.at("value").get<double>(),
            0.5 * (angle.at("high").get<double>() - angle.at("low").get<double>()));
  EXPECT_NE(angle.at("model").get<std::string>().find(
                "+-" + feedflow::format_number(interval.at("value").get<double>(), 2) + " deg"),
            std::string::npos);
  const std::string series = slurp(dir_ / "drum/timeseries.csv");
  EXPECT_NE(series.find("solid_body_fraction"), std::string::npos);
  EXPECT_NE(series.find("surface_height_at_chord_+0.8 [m]"), std::string::npos);
  EXPECT_EQ(series.find("nan"), std::string::npos);
}

}  // namespace
