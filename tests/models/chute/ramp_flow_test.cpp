// Rung L1 chute model (ramp_flow_scheme/solver, chute_release): conservation, well-balancing,
// exact rest inside the Coulomb cone, the uniform flow rule, grid convergence of the deposit.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "models/chute/chute_release.hpp"
#include "models/units/angle.hpp"
#include "tests/support/pine_surface_flow.hpp"

namespace feedflow {
namespace {

using testing::pine_like;

Chute small_chute() {  // reduced-size twin of the seed ramp (2 m ramp, 0.57 m bin, 0.5 m fill)
  Chute c;
  c.angle = 29.5 * kDegree;
  c.width = 0.76;
  c.length = 1.0;
  c.gate_opening = 0.1;
  c.bin_length = 0.3;
  c.bin_height = 0.5;
  c.fill_height = 0.4;
  return c;
}

RampFlowSettings timed(double seconds) {
  RampFlowSettings s;
  s.min_time = seconds;
  s.end_time = seconds;
  return s;
}

// Mass: on-ramp volume plus outflow equals the released volume to 1e-10 relative, through the
// gate, the dam break, the outflow and the stop.
TEST(RampFlow, ReleaseConservesMass) {
  ChuteReleaseOptions o;
  o.cell_size = 0.01;
  const auto r = run_chute_release(small_chute(), pine_like(), o);
  ASSERT_TRUE(r.stopped);
  EXPECT_GT(r.outflow_volume, 0.0);  // something did leave, so the bookkeeping is exercised
  EXPECT_LT(std::abs(r.final_volume + r.outflow_volume - r.initial_volume) / r.initial_volume,
            1e-10);
}

// Well-balanced: a frictionless pool with a horizontal free surface against the lower wall of a
// closed inclined ramp (h = h0 - (x1 - x) tan(theta), dry above) stays at rest for 2 s.
TEST(RampFlow, LakeAtRestStaysAtRest) {
  const RampGrid grid{0.0, 1.0, 100};
  RampPhysics p;
  p.angle = 20 * kDegree;
  p.friction = {0.0, 0.0, 1.0, 1.0, 0.0};  // no friction at all
  p.downstream = RampBoundary::Wall;
  std::vector<double> h(grid.cells);
  for (std::size_t i = 0; i < grid.cells; ++i)
    h[i] = std::max(0.0, 0.2 - (grid.x_end - grid.centre(i)) * std::tan(p.angle));
  const auto r = run_ramp_flow(grid, p, h, {}, timed(2.0));
  EXPECT_GT(r.steps, 500u);
  for (std::size_t i = 0; i < grid.cells; ++i) {
    EXPECT_NEAR(r.thickness[i], h[i], 1e-13) << i;
    EXPECT_LT(std::abs(r.velocity[i]), 1e-12) << i;
  }
}

// Coulomb threshold: a uniform layer thinner than h_stop (tan theta < mu_stop(h)) stays exactly
// at rest (q == 0, h unchanged to the last bit) on a periodic ramp; a thicker one starts.
TEST(RampFlow, StaticLayerStaysExactlyAtRestAndThickOneFlows) {
  const RampGrid grid{0.0, 0.5, 50};
  RampPhysics p;
  p.angle = 29.5 * kDegree;
  p.friction = pine_like();
  p.upstream = p.downstream = RampBoundary::Periodic;
  const double h_stop = stopping_thickness(pine_like(), p.angle).thickness;
  const auto thin = run_ramp_flow(grid, p, std::vector<double>(50, 0.9 * h_stop), {}, timed(1.0));
  for (std::size_t i = 0; i < 50; ++i) {
    EXPECT_EQ(thin.velocity[i], 0.0);
    EXPECT_EQ(thin.thickness[i], 0.9 * h_stop);
  }
  // 10 mm cells, a fifth of h_stop: the slope drive has no reconstruction deficit
  const auto thick = run_ramp_flow(grid, p, std::vector<double>(50, 1.5 * h_stop), {}, timed(0.2));
  EXPECT_GT(thick.velocity[25], 0.01);
}

// Uniform steady flow on a periodic ramp reaches the Pouliquen flow rule Fr = beta h/h_stop on
// coarse cells: 10 mm cells for a 0.1 m layer at 29.5 deg and for a 6.3 mm layer at 37 deg
// (cells thicker than the layer, steps whose gravity impulse exceeds the steady speed).
TEST(RampFlow, UniformFlowMatchesFlowRule) {
  const RampGrid grid{0.0, 0.1, 10};
  RampPhysics p;
  p.friction = pine_like();
  p.upstream = p.downstream = RampBoundary::Periodic;
  for (const auto& [angle, h, seconds] : {std::tuple{29.5, 0.1, 20.0}, std::tuple{37.0, 6.3e-3, 2.0}}) {
    p.angle = angle * kDegree;
    const auto r = run_ramp_flow(grid, p, std::vector<double>(10, h), {}, timed(seconds));
    const double expected = flow_rule_velocity(pine_like(), h, p.angle);
    EXPECT_NEAR(r.velocity[5] / expected, 1.0, 1e-6) << angle << ": " << r.velocity[5];
    EXPECT_NEAR(r.thickness[5], h, 1e-12 * h);
  }
}

double mid_deposit(double cell_size) {
  ChuteReleaseOptions o;
  o.cell_size = cell_size;
  const auto r = run_chute_release(small_chute(), pine_like(), o);
  EXPECT_TRUE(r.stopped) << cell_size;
  return r.probe_thickness;
}

// Grid convergence of the release (reduced twin of the seed ramp): the mid-ramp deposit at
// 20 / 10 / 5 mm cells agrees to 0.5 % and lies within 1.5 % of h_stop of the law (48.6 mm);
// the first-order scheme gave 93 / 68 / 63 mm here.
TEST(RampFlow, DepositConvergesUnderRefinement) {
  const double h20 = mid_deposit(0.02), h10 = mid_deposit(0.01), h5 = mid_deposit(0.005);
  const double h_stop = stopping_thickness(pine_like(), 29.5 * kDegree).thickness;
  std::printf("mid-ramp deposit: %.2f / %.2f / %.2f mm at dx = 20 / 10 / 5 mm (h_stop %.2f)\n",
              h20 * 1e3, h10 * 1e3, h5 * 1e3, h_stop * 1e3);
  EXPECT_LT(std::abs(h10 - h5), 0.005 * h5);
  EXPECT_LT(std::abs(h20 - h5), 0.005 * h5);
  for (double h : {h20, h10, h5}) EXPECT_NEAR(h / h_stop, 1.0, 0.015);
}

// Outputs: the front advances down the ramp, the recorded velocities are positive while it
// flows, and the stop criterion ends the run with the flow exactly at rest.
TEST(RampFlow, RecordsFrontAndStops) {
  ChuteReleaseOptions o;
  o.cell_size = 0.02;
  const auto r = run_chute_release(small_chute(), pine_like(), o);
  ASSERT_GT(r.samples.size(), 5u);
  EXPECT_GT(r.samples[3].front_position, r.samples[1].front_position);
  EXPECT_GT(r.samples[2].mean_velocity, 0.0);
  EXPECT_NEAR(r.samples.back().front_position, 0.99, 1e-9);  // material reached the end
  EXPECT_TRUE(r.stopped);
  for (double u : r.velocity) EXPECT_LT(std::abs(u), 1e-2);
}

}  // namespace
}  // namespace feedflow
