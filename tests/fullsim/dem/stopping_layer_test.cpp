// The stopping layer (Pouliquen's h_stop on the particle rung): a periodic layer on the seed's
// rough ramp, filled under gravity normal to the ramp, then tilted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <vector>

#include "fullsim/dem/scene/stopping_layer.hpp"
#include "models/units/angle.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

// The twin's spheres (R = 3 mm, Hertz, Table 2), a layer `diameters` thick over 20 diameters of
// an 18 mm slab, filled for a ramp of `angle_deg`.
std::unique_ptr<StoppingLayerScene> filled_layer(double angle_deg, double diameters,
                                                 std::ostream& log) {
  StoppingLayerSpec spec;
  spec.angle = angle_deg * kDegree;
  spec.thickness = diameters * 6e-3;
  spec.slab_depth = 0.018;
  auto layer = std::make_unique<StoppingLayerScene>(dem_test::pine_twin_settings(), spec);
  layer->fill(log);
  return layer;
}

// The rain fill covers the whole periodic length: the mean of the highest tops per diameter is
// within a radius below the thickness asked (measured 28.4 mm for 30 mm) and none is above it,
// and the settled layer is at rest.
TEST(StoppingLayer, FillCoversTheLengthToTheThickness) {
  std::ostringstream log;
  const auto layer = filled_layer(30.0, 5.0, log);
  EXPECT_TRUE(layer->fill_report().settled) << log.str();
  EXPECT_LE(layer->thickness(), 0.030 + 1e-12);
  EXPECT_GT(layer->thickness(), 0.030 - 3e-3);
  EXPECT_TRUE(layer->at_rest());
  EXPECT_NEAR(layer->length(), 0.120, 1e-12);  // 20 diameters, whole teeth
}

// Below the friction angle no layer flows, however thick: launched at 0.5 sqrt(g h) on the steep
// ramp and turned to 20 deg, an eight-diameter layer comes to rest (measured: 0.36 s), and the
// periodic layer keeps every sphere.
TEST(StoppingLayer, EveryLayerStopsBelowTheFrictionAngle) {
  std::ostringstream log;
  const auto layer = filled_layer(20.0, 8.0, log);
  const std::size_t n = layer->engine().particles().size();
  layer->launch(log);
  EXPECT_GE(layer->launch_speed(), 0.5 * std::sqrt(9.81 * 0.048));
  const LayerOutcome o = run_layer(*layer, 2.0, log);
  EXPECT_TRUE(o.at_rest) << log.str();
  EXPECT_LT(o.time, 1.0);
  EXPECT_EQ(layer->engine().particles().size(), n);
}

// Pouliquen's h_stop: at one angle between the two friction angles a thin layer stops and a
// thick one flows. At 37 deg (measured with these spheres: 2 diameters at rest after 0.6 s, 5
// diameters running steadily at 0.54 m/s after 2 s, 0.69 m/s after 4 s); the thick one is
// told apart before the run's end, once it runs away past 1.5 times its launch speed.
TEST(StoppingLayer, AThinLayerStopsWhereAThickOneFlows) {
  std::ostringstream log;
  const auto thin = filled_layer(37.0, 2.0, log);
  thin->launch(log);
  const LayerOutcome stops = run_layer(*thin, 2.0, log);
  const auto thick = filled_layer(37.0, 5.0, log);
  thick->launch(log);
  const LayerOutcome flows = run_layer(*thick, 2.0, log);
  EXPECT_TRUE(stops.at_rest) << log.str();
  EXPECT_FALSE(stops.ran_away) << log.str();
  EXPECT_LT(stops.peak_speed, StoppingLayerScene::kRunAwaySpeedRatio * thin->launch_speed());
  EXPECT_FALSE(flows.at_rest) << log.str();
  EXPECT_TRUE(flows.ran_away) << log.str();
  EXPECT_LT(flows.time, 2.0) << log.str();
  EXPECT_GE(flows.speed, StoppingLayerScene::kRunAwaySpeedRatio * thick->launch_speed());
  // A flowing layer dilates: its measured thickness grows beyond the settled one.
  EXPECT_GT(flows.thickness, thick->spec().thickness);
}

// The slowing rule on series shaped as the seed's layers at 35 deg: one held at its launch speed
// flows steadily (ratio 1), one falling from its launch speed at 2 s to 0.36 of it at 4 s still
// slows (about 0.6), and one sampled for less than the lag has no earlier speed (1); so does
// the 82.4 mm layer at 34 deg (0.86 at 4 s), while a steady layer swinging by 15 % passes.
TEST(StoppingLayer, ASlowingLayerIsToldFromASteadyOne) {
  const auto series = [](auto speed) {
    TimeSeries s({{"time_after_tilt", "s"}, {"downslope_speed", "m/s"}});
    for (int k = 0; k <= 300; ++k) s.add_row({0.02 * k, speed(0.02 * k)});  // 6 s
    return s;
  };
  const TimeSeries steady = series([](double) { return 0.4; });
  const TimeSeries slowing =
      series([](double t) { return t < 2.0 ? 0.37 : 0.37 * (1.0 - 0.32 * (t - 2.0)); });
  EXPECT_NEAR(layer_slowing_ratio(steady, 0, 1, 4.0), 1.0, 1e-12);
  EXPECT_GE(layer_slowing_ratio(steady, 0, 1, 4.0), kLayerSlowingRatio);
  EXPECT_NEAR(layer_slowing_ratio(slowing, 0, 1, 4.0), 0.59, 0.02);
  EXPECT_LT(layer_slowing_ratio(slowing, 0, 1, 4.0), kLayerSlowingRatio);
  EXPECT_EQ(layer_slowing_ratio(slowing, 0, 1, 0.4), 1.0);
  // The seed's 82.4 mm layer at 34 deg, its mean speed every 0.2 s after the tilt (particle
  // snapshots): falling from 0.51 to 0.30 m/s over 4 s with a pause; at 4 s it still slows.
  const std::vector<double> at_34{0.456, 0.509, 0.513, 0.497, 0.479, 0.467, 0.430,
                                  0.416, 0.365, 0.351, 0.319, 0.325, 0.329, 0.336,
                                  0.355, 0.347, 0.336, 0.312, 0.308, 0.290, 0.298};
  const TimeSeries falling = series([&](double t) {
    const double k = std::min(t / 0.2, at_34.size() - 1.0);
    const std::size_t i = std::min(static_cast<std::size_t>(k), at_34.size() - 2);
    return at_34[i] + (k - i) * (at_34[i + 1] - at_34[i]);
  });
  EXPECT_LT(layer_slowing_ratio(falling, 0, 1, 4.0), kLayerSlowingRatio);
  // A steady layer whose speed swings by 15 % over 1.4 s passes the rule within a swing.
  const TimeSeries swinging = series(
      [](double t) { return 0.45 * (1.0 + 0.15 * std::sin(2.0 * std::numbers::pi * t / 1.4)); });
  bool steady_within_a_swing = false;
  for (double t = 4.0; t <= 5.4; t += 0.02)
    steady_within_a_swing =
        steady_within_a_swing || layer_slowing_ratio(swinging, 0, 1, t) >= kLayerSlowingRatio;
  EXPECT_TRUE(steady_within_a_swing);
}

}  // namespace
}  // namespace feedflow
