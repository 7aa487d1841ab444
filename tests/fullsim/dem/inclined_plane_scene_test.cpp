// The inclined-plane scene (issue 6): the deposit measurement and the reduced twin of the
// seed's ramp at 29.5 and 37 deg.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "fullsim/dem/scene/inclined_plane_scene.hpp"
#include "models/units/angle.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"
#include "tests/fullsim/dem/mass_books.hpp"

namespace feedflow {
namespace {

// The deposit height of a bin is its highest particle top above the surface, mid-ramp is the
// mean over the middle 10 %, and particles off the ramp (in the bin, x < 0) do not count.
TEST(DepositProfile, HighestTopPerBinAndMidRamp) {
  ParticleStore p;
  p.add(Vec3(-0.05, 0, 0.5), 0.001, 390);    // in the bin
  p.add(Vec3(0.495, 0, 0.010), 0.001, 390);  // mid-ramp bin [0.49, 0.50)
  p.add(Vec3(0.497, 0, 0.020), 0.001, 390);  // same bin, higher
  p.add(Vec3(0.505, 0, 0.004), 0.001, 390);  // next bin
  p.add(Vec3(0.9, 0, 0.002), 0.001, 390);
  const DepositProfile d = measure_deposit(BedView(p, p.size(), DemRanks::one()), 1.0, 0.001, 0.01);
  ASSERT_EQ(d.height.size(), 100u);
  EXPECT_NEAR(d.height[49], 0.020, 1e-12);
  EXPECT_NEAR(d.height[50], 0.004, 1e-12);
  EXPECT_NEAR(d.front, 0.905, 1e-12);
  // bins 45..54 (centres within 0.05 of 0.5): two non-empty, eight empty
  EXPECT_NEAR(d.mid_ramp.value, (0.020 + 0.004) / 10.0, 1e-12);
}

// Reduced twin of the seed's inclined plane: bin 70 x 60 mm fill (about 1/8 of the seed's
// 570 x 500 mm), ramp 0.25 m, particles coarse-grained to R = 3 mm (2x), an 18 mm slab (two
// neighbour cutoffs), Hertz + Mindlin + cdt with Table 2's E, nu, e, mu, mu_r (~360 particles
// after the rain fill).
// The gate is 60 mm (10 diameters) at both angles: scaled down, the seed's openings (35 and
// 13.5 cm) would be 3 to 9 diameters and the narrow one jams; the seed found the opening has a
// minor effect on h_stop (data.md 3).
std::unique_ptr<InclinedPlaneScene> filled_plane(double angle_deg, std::ostream& log) {
  const DemSettings s = dem_test::pine_twin_settings();
  InclinedPlaneSpec spec;
  spec.angle = angle_deg * kDegree;
  spec.ramp_length = 0.25;
  spec.bin_length = 0.07;
  spec.bin_height = 0.12;
  spec.fill_height = 0.06;
  spec.gate_opening = 0.06;
  spec.slab_depth = 0.018;
  auto plane = std::make_unique<InclinedPlaneScene>(s, spec);
  plane->fill(log);
  return plane;
}

// Runs a filled plane from the release until the flow has stopped (5 s at most).
void run_to_rest(InclinedPlaneScene& plane, std::ostream& log) {
  plane.open_gate(log);
  while (plane.engine().time() - plane.release_time() < 0.2 || !plane.flow_stopped()) {
    plane.engine().advance_to(plane.engine().time() + 0.02);
    if (plane.engine().time() - plane.release_time() > 5.0) break;
  }
}

DepositProfile run_plane(double angle_deg) {
  std::ostringstream log;
  const auto plane = filled_plane(angle_deg, log);
  run_to_rest(*plane, log);
  const auto d = plane->deposit();
  std::cerr << log.str() << angle_deg << " deg: " << plane->engine().particles().size()
            << " particles, stopped after " << plane->engine().time() - plane->release_time()
            << " s, h_stop(mid) " << d.mid_ramp.value * 1e3 << " mm, front " << d.front << " m, profile";
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
// first quarter of the ramp (measured with the rain fill: 22.0 against 12.0 mm; 22.3 against
// 15.6 before the teeth were placed by count, a round-off apart; with the former lattice fill
// 16.3 against 12.5) and at its highest (24.8 against 16.1 mm; before, 27.8 against 18.3). Not
// at mid-ramp: the twin's small bin barely feeds a layer over the whole ramp (10.7 against 9.8
// mm with the rain fill, 3 against 7 with the looser lattice fill); the full-size run (LONG_)
// compares it.
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

// Deepest overlap between particles (minimum image across the slab) and with the floor, the
// bin's back wall and the closed gate.
double deepest_plane_overlap(const InclinedPlaneScene& plane) {
  const ParticleStore& p = plane.engine().particles();
  const SimulationBox& box = plane.engine().box();
  double deepest = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.position[i];
    const double r = p.radius[i];
    deepest = std::max({deepest, r - x.z(), r - (x.x() + plane.spec().bin_length), r + x.x()});
    for (std::size_t j = i + 1; j < p.size(); ++j)
      deepest = std::max(deepest, r + p.radius[j] - box.minimum_image(x - p.position[j]).norm());
  }
  return deepest;
}

// The rain fill of the twin's bin reaches the fill height at both angles: it rained in more than
// the trim keeps, settled against the closed gate below the seed's 1 mm/s, and after the trim
// every quarter of the bin's length (the back wall's too, which the rain falling down the slope
// feeds least) has its highest centre within a diameter below the fill height; no sphere
// overlaps another or a wall by more than 5 % of R (a bed settled under its weight).
TEST(InclinedPlaneTwin, RainFillReachesTheFillHeightSettledWithoutOverlaps) {
  for (double angle : {29.5, 37.0}) {
    std::ostringstream log;
    const auto plane = filled_plane(angle, log);
    const FillReport& f = plane->fill_report();
    const double r = 3e-3, H = plane->spec().fill_height, L = plane->spec().bin_length;
    EXPECT_TRUE(f.target_reached) << angle;
    EXPECT_TRUE(f.settled) << angle;
    EXPECT_LT(f.final_max_speed, 1e-3) << angle;
    EXPECT_GT(f.trimmed_count, 10u) << angle;
    const ParticleStore& p = plane->engine().particles();
    EXPECT_EQ(p.size() + f.trimmed_count, f.inserted_count) << angle;
    double top[4] = {-1.0, -1.0, -1.0, -1.0};
    for (const Vec3& x : p.position) {
      const int q = std::clamp(static_cast<int>((x.x() + L) / (0.25 * L)), 0, 3);
      top[q] = std::max(top[q], x.z());
    }
    for (int q = 0; q < 4; ++q) {
      EXPECT_LE(top[q], H + 1e-12) << angle << " deg, quarter " << q;
      EXPECT_GT(top[q], H - 2.0 * r) << angle << " deg, quarter " << q;
    }
    std::cerr << angle << " deg: " << p.size() << " particles after the fill, deepest overlap "
              << deepest_plane_overlap(*plane) / r << " R, tops " << top[0] << ' ' << top[1] << ' '
              << top[2] << ' ' << top[3] << " m\n"
              << log.str();
    EXPECT_LT(deepest_plane_overlap(*plane), 0.05 * r) << angle;
  }
}

// Mass bookkeeping at 37 deg, where the flow runs off the ramp's end: every rained-in sphere is
// in the domain, taken by the outlet sink or trimmed, exactly once, and the masses add up to the
// inserted mass to round-off.
TEST(InclinedPlaneTwin, RainedMassIsInTheDomainSunkOrTrimmed) {
  std::ostringstream log;
  const auto plane = filled_plane(37.0, log);
  run_to_rest(*plane, log);
  const FillReport& f = plane->fill_report();
  const DemEngine& e = plane->engine();
  const OutletSink& sink = *e.outlet_sink();
  ASSERT_GT(sink.removed_count(), 5u);  // it ran off the end
  dem_test::expect_mass_books_balance(e, f);
}

}  // namespace
}  // namespace feedflow
