// A chute's stopping layer through the simulate path (tests/data/dem_layer_twin.toml: 37 deg,
// R = 3 mm, Hertz): the case's [dem] stopping_layer turns the chute's DEM run into the layer,
// which answers whether it rests, with the reduced h_stop beside it; the key belongs to chutes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "designer/case/case_loader.hpp"
#include "designer/simulate/dem_case_settings.hpp"
#include "designer/simulate/dem_layer_adapter.hpp"
#include "designer/simulate/simulation.hpp"
#include "fullsim/dem/dem_checkpoint.hpp"
#include "models/core/errors.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

namespace fs = std::filesystem;

SimulationRequest layer_request(std::vector<SetOverride> sets, const std::string& name) {
  SimulationRequest r;
  r.case_data = load_case("tests/data/dem_layer_twin.toml", sets);
  r.solver = Solver::dem;
  r.out =
      fs::temp_directory_path() / ("feedflow_demlayer_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(r.out);
  fs::create_directories(r.out);
  r.progress = false;
  return r;
}

// Two diameters at 37 deg come to rest (measured 0.6 s after the tilt with these spheres, run by
// the scene alone): through simulate the run stops there, at rest, with a settled thickness
// within a radius of the trim, and the reduced h_stop stands beside it.
TEST(DemLayerSimulation, TwoDiametersComeToRestAtThirtySevenDegrees) {
  const SimulationRequest r = layer_request({}, "rest");
  const SimulationOutcome o = simulate(r);
  const Estimate* state = find_estimate(o.record.results, "layer_state");
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(std::get<std::string>(state->value), "at rest");
  EXPECT_EQ(state->rung, Rung::L3);
  const double after = std::get<double>(find_estimate(o.record.results, "time_after_tilt")->value);
  EXPECT_GE(after, 0.1);  // the tilt's first jolt does not count
  EXPECT_LT(after, 2.0);
  const double h = std::get<double>(find_estimate(o.record.results, "layer_thickness")->value);
  EXPECT_GT(h, 0.012 - 0.003);
  EXPECT_LT(h, 0.012 + 0.003);
  EXPECT_LT(std::get<double>(find_estimate(o.record.results, "layer_speed")->value), 0.05);
  EXPECT_NE(find_estimate(o.record.results, reduced_model_key("stopping_thickness")), nullptr);
  ASSERT_FALSE(o.series.empty());
  EXPECT_EQ(o.series.columns()[2].name, "downslope_speed");
  fs::remove_all(r.out);
}

// [dem] end_time bounds a layer's run, it does not fix its length: with 3 s set the layer still
// ends once at rest, before 2 s.
TEST(DemLayerSimulation, EndTimeIsALimitNotALength) {
  const SimulationRequest r = layer_request({parse_set_override("dem.end_time=3s")}, "limit");
  const SimulationOutcome o = simulate(r);
  EXPECT_EQ(std::get<std::string>(find_estimate(o.record.results, "layer_state")->value),
            "at rest");
  EXPECT_LT(std::get<double>(find_estimate(o.record.results, "time_after_tilt")->value), 2.0);
  fs::remove_all(r.out);
}

// A restart continues the tilted layer: run to 0.1 s after the tilt (checkpoint), then from it
// to 0.2 s straight, and to 0.15 s (checkpoint) then on to 0.2 s: the same particles' bits and
// series rows, whose time after the tilt is read from the checkpoint (not the restart's own
// start).
TEST(DemLayerSimulation, ARestartContinuesTheTiltedLayer) {
  SimulationRequest r = layer_request({}, "restart");
  const fs::path root = r.out;
  const auto run = [&](const std::string& name, double time, const fs::path& restart) {
    r.out = root / name;
    fs::create_directories(r.out);
    r.end_time = time;
    r.restart = restart;
    return simulate(r);
  };
  run("a", 0.1, {});
  const SimulationOutcome straight = run("b", 0.2, root / "a" / "checkpoint.h5");
  run("c", 0.15, root / "a" / "checkpoint.h5");
  const SimulationOutcome resumed = run("d", 0.2, root / "c" / "checkpoint.h5");
  const DemCheckpoint x = read_dem_checkpoint(root / "b" / "checkpoint.h5");
  const DemCheckpoint y = read_dem_checkpoint(root / "d" / "checkpoint.h5");
  EXPECT_EQ(x.step, y.step);
  EXPECT_EQ(x.particles.position, y.particles.position);
  EXPECT_EQ(x.particles.velocity, y.particles.velocity);
  EXPECT_EQ(straight.series.rows(), resumed.series.rows());
  ASSERT_FALSE(resumed.series.empty());
  EXPECT_NEAR(resumed.series.rows().back()[1], 0.2, 1e-4);  // after the tilt, to a step or two
  fs::remove_all(root);
}

// A layer thinner than one sphere is refused naming the key; on a hopper the key is refused too.
TEST(DemLayerSimulation, TheKeyIsCheckedAndBelongsToChutes) {
  SimulationRequest thin = layer_request({{"dem.stopping_layer", "4 mm"}}, "thin");
  try {
    (void)simulate(thin);
    FAIL() << "a 4 mm layer of 6 mm spheres ran";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dem.stopping_layer"), std::string::npos) << e.what();
  }
  SimulationRequest hopper = thin;
  hopper.case_data = load_case("tests/data/dem_hopper_twin.toml",
                               std::vector<SetOverride>{{"dem.stopping_layer", "12 mm"}});
  try {
    (void)simulate(hopper);
    FAIL() << "a hopper took a stopping layer";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("chute"), std::string::npos) << e.what();
  }
  fs::remove_all(thin.out);
}

// The layer's periodic length is the case's, in whole saw teeth (one diameter each: 45 mm of 6 mm
// spheres is 8 teeth, 48 mm), 20 diameters without it; without a stopping layer the key is
// refused naming it.
TEST(DemLayerSimulation, ThePeriodicLengthIsTheCasesInWholeTeeth) {
  const auto length_of = [](std::vector<SetOverride> sets) {
    const Case c = load_case("tests/data/dem_layer_twin.toml", sets);
    const DemSettings settings = dem_case_settings(c);
    return StoppingLayerScene(settings, stopping_layer_spec(c, settings)).length();
  };
  EXPECT_NEAR(length_of({{"dem.stopping_layer_length", "45 mm"}}), 0.048, 1e-12);
  EXPECT_NEAR(length_of({}), 0.120, 1e-12);
  Case chute_run = load_case("tests/data/dem_layer_twin.toml",
                             std::vector<SetOverride>{{"dem.stopping_layer_length", "45 mm"}});
  chute_run.dem.stopping_layer.reset();  // the bin released down the ramp
  try {
    (void)dem_case_settings(chute_run);
    FAIL() << "a periodic length without a stopping layer was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dem.stopping_layer_length"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace feedflow
