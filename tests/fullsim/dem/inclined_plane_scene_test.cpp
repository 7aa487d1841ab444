// The inclined-plane scene (issue 6): the deposit measurement and the reduced twin of the
// seed's ramp at 29.5 and 37 deg.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>

#include "fullsim/dem/scene/inclined_plane_scene.hpp"
#include "tests/support/pine_table2.hpp"

namespace feedflow {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The deposit height of a bin is its highest particle top above the surface, mid-ramp is the
// mean over the middle 10 %, and particles off the ramp (in the bin, x < 0) do not count.
TEST(DepositProfile, HighestTopPerBinAndMidRamp) {
  ParticleStore p;
  p.add(Vec3(-0.05, 0, 0.5), 0.001, 390);    // in the bin
  p.add(Vec3(0.495, 0, 0.010), 0.001, 390);  // mid-ramp bin [0.49, 0.50)
  p.add(Vec3(0.497, 0, 0.020), 0.001, 390);  // same bin, higher
  p.add(Vec3(0.505, 0, 0.004), 0.001, 390);  // next bin
  p.add(Vec3(0.9, 0, 0.002), 0.001, 390);
  const DepositProfile d = measure_deposit(p, 1.0, 0.001, 0.01);
  ASSERT_EQ(d.height.size(), 100u);
  EXPECT_NEAR(d.height[49], 0.020, 1e-12);
  EXPECT_NEAR(d.height[50], 0.004, 1e-12);
  EXPECT_NEAR(d.front, 0.905, 1e-12);
  // bins 45..54 (centres within 0.05 of 0.5): two non-empty, eight empty
  EXPECT_NEAR(d.mid_ramp_height, (0.020 + 0.004) / 10.0, 1e-12);
}

// Reduced twin of the seed's inclined plane: bin 70 x 60 mm fill (about 1/8 of the seed's
// 570 x 500 mm), ramp 0.25 m, particles coarse-grained to R = 3 mm (2x), an 18 mm slab (two
// neighbour cutoffs), Hertz + Mindlin + cdt with Table 2's E, nu, e, mu, mu_r (~220 particles).
// The gate is 60 mm (10 diameters) at both angles: scaled down, the seed's openings (35 and
// 13.5 cm) would be 3 to 9 diameters and the narrow one jams; the seed found the opening has a
// minor effect on h_stop (data.md 3).
DepositProfile run_plane(double angle_deg) {
  DemSettings s;
  s.material.particle = {3e-3, 390.0};
  s.material.particle_particle = testing::pine_table2_particle_particle();
  s.material.particle_wall = testing::pine_table2_particle_wall();
  s.law = {NormalLaw::hertz, TangentialLaw::mindlin, RollingLaw::cdt, CohesionLaw::none};
  s.quiet = true;
  InclinedPlaneSpec spec;
  spec.angle = angle_deg * kDeg;
  spec.ramp_length = 0.25;
  spec.bin_length = 0.07;
  spec.bin_height = 0.12;
  spec.fill_height = 0.06;
  spec.gate_opening = 0.06;
  spec.slab_depth = 0.018;
  InclinedPlaneScene plane(s, spec);
  std::ostringstream log;
  plane.fill(log);
  plane.open_gate(log);
  while (plane.engine().time() - plane.release_time() < 0.2 || !plane.flow_stopped()) {
    plane.engine().run_until(plane.engine().time() + 0.02);
    if (plane.engine().time() - plane.release_time() > 5.0) break;
  }
  const auto d = plane.deposit();
  std::cerr << log.str() << angle_deg << " deg: " << plane.engine().particles().size()
            << " particles, stopped after " << plane.engine().time() - plane.release_time()
            << " s, h_stop(mid) " << d.mid_ramp_height * 1e3 << " mm, front " << d.front << " m, profile";
  for (std::size_t b = 0; b < d.x.size(); b += 3) std::cerr << ' ' << d.height[b] * 1e3;
  std::cerr << '\n';
  return d;
}

double mean_height(const DepositProfile& d, double from, double to) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t b = 0; b < d.x.size(); ++b)
    if (d.x[b] >= from && d.x[b] < to) {
      sum += d.height[b];
      ++n;
    }
  return n ? sum / n : 0.0;
}

// The seed's trend (Fig. 5B): the deposit at 29.5 deg is thicker than at 37 deg, here over the
// first quarter of the ramp (measured: 16.3 against 12.5 mm) and at its highest (20.2 against
// 16.4 mm). Not at mid-ramp: the twin's small bin runs out at 29.5 deg before a layer has passed
// the whole ramp (a heap with single grains ahead, 3 mm at mid-ramp against the 37 deg layer's
// 7); the full-size run (tests/long) compares mid-ramp.
TEST(InclinedPlaneTwin, DepositThickerAt29_5ThanAt37) {
  const auto shallow = run_plane(29.5), steep = run_plane(37.0);
  std::cerr << "first quarter: " << mean_height(shallow, 0.0, 0.0625) * 1e3 << " / "
            << mean_height(steep, 0.0, 0.0625) * 1e3 << " mm, highest: "
            << *std::max_element(shallow.height.begin(), shallow.height.end()) * 1e3 << " / "
            << *std::max_element(steep.height.begin(), steep.height.end()) * 1e3 << " mm\n";
  EXPECT_GT(mean_height(shallow, 0.0, 0.0625), mean_height(steep, 0.0, 0.0625) + 1e-3);
  EXPECT_GT(*std::max_element(shallow.height.begin(), shallow.height.end()),
            *std::max_element(steep.height.begin(), steep.height.end()) + 2e-3);
  // Both flows left the gate: there is a deposit beyond a quarter of the ramp.
  EXPECT_GT(shallow.front, 0.0625);
  EXPECT_GT(steep.front, 0.0625);
}

}  // namespace
}  // namespace feedflow
