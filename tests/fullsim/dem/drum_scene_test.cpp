// The rotating-drum scene (issue 6): the free-surface fit, the regime classification, and the
// reduced twin of the seed drum at 10, 50 and 300 rpm (the seed's labels: rolling, cascading,
// centrifuging; data.md 4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <sstream>

#include "fullsim/dem/scene/drum_angle_watch.hpp"
#include "fullsim/dem/scene/drum_scene.hpp"
#include "models/units/angle.hpp"
#include "tests/support/pine_table2.hpp"

namespace feedflow {
namespace {

// A bed of particles (R = 1.5 mm) packed on a square grid in the lower part of a 145 mm drum
// whose surface is the line through the axis tilted by `tilt` (raised towards -x).
std::vector<SurfacePoint> tilted_bed(double tilt, double airborne_height = 0.0) {
  const double R = 0.0725, r = 1.5e-3;
  std::vector<SurfacePoint> p;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (double x = -R; x <= R; x += 2 * r)
    for (double z = -R; z <= R; z += 2 * r)
      if (std::hypot(x, z) < R - r && z <= -std::tan(tilt) * x) p.push_back({x + u(rng) * r, z + u(rng) * r});
  if (airborne_height > 0.0)  // a few particles in flight above the middle of the bed
    for (double x = -0.02; x <= 0.02; x += 0.01) p.push_back({x, -std::tan(tilt) * x + airborne_height});
  return p;
}

// The fit returns the tilt of a synthetic bed within a degree, and particles in flight above
// the bed do not pull the surface up.
TEST(DrumFreeSurface, FitReturnsTheTiltOfASyntheticBed) {
  for (double tilt : {0.0, 20.0, 35.0, 45.0}) {
    const auto fit = fit_drum_surface(
        bed_surface_points(tilted_bed(tilt * kDegree, 0.02), 1.5e-3, 0.0725), 0.0725);
    ASSERT_TRUE(fit.valid);
    EXPECT_NEAR(-fit.slope_angle / kDegree, tilt, 1.0) << "tilt " << tilt;
    // A flat surface bends by no more than the grid's steps (2 radii = 0.04 R) allow.
    EXPECT_LT(fit.bulge, 0.1) << "tilt " << tilt;
  }
}

// A column with more grains in flight above the bed than the first lists hold (20, each 3
// radii above the last) is told from deeper lists: its surface point is the bed's top, as for
// its neighbours, and the columns' tops merged from two halves of the bed give the same points.
TEST(DrumFreeSurface, DeepFlightIsToldAndHalvesMergeToTheWhole) {
  const double R = 0.0725, r = 1.5e-3;
  std::vector<SurfacePoint> p = tilted_bed(0.0);
  for (int k = 1; k <= 20; ++k) p.push_back({0.0, 0.01 + 3.0 * r * k});
  const auto surface = bed_surface_points(p, r, R);
  double top = -1.0;
  for (const auto& q : p) top = q.z < 0.005 ? std::max(top, q.z) : top;
  const auto at_axis = std::find_if(surface.begin(), surface.end(), [&](const SurfacePoint& s) { return std::abs(s.x) < r; });
  ASSERT_NE(at_axis, surface.end());
  EXPECT_LT(at_axis->z, 0.005);  // the bed, not a grain in flight
  EXPECT_GT(at_axis->z, top - 2.5 * r);
  // The second half's tops merged into the first's as a reduction over ranks does.
  const std::vector<SurfacePoint> first(p.begin(), p.begin() + static_cast<long>(p.size() / 2)),
      second(p.begin() + static_cast<long>(p.size() / 2), p.end());
  const auto merged = bed_surface_points(first, r, R, [&](ColumnTops& t) {
    const ColumnTops other = column_tops(second, r, R, t.depth);
    for (std::size_t c = 0; c < t.count.size(); ++c) {
      t.count[c] += other.count[c];
      std::vector<double> both(t.z.begin() + static_cast<long>(c * t.depth), t.z.begin() + static_cast<long>((c + 1) * t.depth));
      both.insert(both.end(), other.z.begin() + static_cast<long>(c * t.depth), other.z.begin() + static_cast<long>((c + 1) * t.depth));
      std::sort(both.begin(), both.end(), std::greater<>());
      std::copy_n(both.begin(), t.depth, t.z.begin() + static_cast<long>(c * t.depth));
    }
  });
  ASSERT_EQ(merged.size(), surface.size());
  for (std::size_t i = 0; i < surface.size(); ++i) {
    EXPECT_EQ(merged[i].x, surface[i].x);
    EXPECT_EQ(merged[i].z, surface[i].z);
  }
}

// An S-shaped surface (a cubic of amplitude 0.2 R) is measured as a bulge near 0.2.
TEST(DrumFreeSurface, SShapedSurfaceShowsItsBulge) {
  const double R = 0.0725, r = 1.5e-3;
  std::vector<SurfacePoint> p;
  for (double x = -R; x <= R; x += 2 * r)
    for (double z = -R; z <= R; z += 2 * r) {
      const double s = x / (0.8 * R);
      if (std::hypot(x, z) < R - r && z <= -0.7 * x + 0.2 * R * 2.6 * (s * s * s - s)) p.push_back({x, z});
    }
  const auto fit = fit_drum_surface(bed_surface_points(p, r, R), R);
  ASSERT_TRUE(fit.valid);
  EXPECT_GT(fit.bulge, 0.1);
}

DrumBedState state(double bulge, double swing, double airborne, double over_top, double solid, double shell) {
  return {bulge, swing, airborne, over_top, solid, shell};
}

// Each regime of the classification follows from a constructed state that shows its mark,
// and the order of the tests makes a centrifuging bed (which also has a "bulge") centrifuging.
TEST(DrumBedRegime, ConstructedStatesGetTheirRegimes) {
  EXPECT_EQ(classify_drum_bed(state(0.03, 0.1, 0.0, 0.0, 0.3, 0.95)).regime, DrumBedRegime::rolling);
  EXPECT_EQ(classify_drum_bed(state(0.1, 0.1, 0.005, 0.0, 0.3, 0.95)).regime, DrumBedRegime::cascading);
  EXPECT_EQ(classify_drum_bed(state(0.3, 0.1, 0.0, 0.0, 0.3, 0.95)).regime, DrumBedRegime::cascading);
  EXPECT_EQ(classify_drum_bed(state(0.4, 0.1, 0.10, 0.05, 0.3, 0.95)).regime, DrumBedRegime::cataracting);
  EXPECT_EQ(classify_drum_bed(state(0.5, 1.0, 0.01, 0.2, 0.95, 0.99)).regime, DrumBedRegime::centrifuging);
  EXPECT_EQ(classify_drum_bed(state(0.03, 0.2, 0.0, 0.0, 0.85, 0.95)).regime, DrumBedRegime::slumping);
  EXPECT_EQ(classify_drum_bed(state(0.03, 0.1, 0.0, 0.0, 0.0, 0.1)).regime, DrumBedRegime::slipping);
}

// In a small bed a fraction in flight below one particle is not taken for cascading: 0.12 % of
// 771 particles (0.9 of a particle on average) stays rolling, the same fraction of 3 000 cascades.
TEST(DrumBedRegime, FlightBelowOneParticleIsNotCascading) {
  DrumBedState small = state(0.07, 0.2, 0.0012, 0.0, 0.3, 0.9);
  small.particles = 771;
  EXPECT_EQ(classify_drum_bed(small).regime, DrumBedRegime::rolling);
  DrumBedState large = small;
  large.particles = 3000;
  EXPECT_EQ(classify_drum_bed(large).regime, DrumBedRegime::cascading);
}

// Reduced twin of the seed drum (D = 145 mm, 50 % fill, same Froude numbers): a periodic axial
// slab 18 mm deep (the neighbour cutoff needs two cutoffs) of particles coarse-grained to
// R = 3 mm (2x the seed's: d/D = 0.041 instead of 0.021, ~760 instead of ~70 000 particles),
// Hertz + Mindlin + cdt with Table 2's E, nu, e, mu and mu_r (the seed's hysteretic law needs a
// 20x smaller step). The slab has no turning end plates: its shell takes the case's wall
// friction (20 deg) instead of Table 2's 0.2, with which the whole bed slips on the shell
// (measured; reduced_models.md 4: no slip needs mu_w > (r_g/R) sin beta = 0.24 at 35 deg).
DemSettings twin_settings() {
  DemSettings s;
  s.material.particle = {3e-3, 390.0};
  s.material.particle_particle = testing::pine_table2_particle_particle();
  s.material.particle_wall = testing::pine_table2_contact(std::tan(20 * kDegree), 0.6);
  s.law = choose_contact_law("hertz", "mindlin", "cdt", "none");
  return s;
}

// The twin rain-filled and settled once per test process; each speed turns a copy of it.
struct FilledTwin {
  DemCheckpoint bed;
  FillReport fill;
  double fill_line = 0.0;  // [m]
};

const FilledTwin& filled_twin() {
  static const FilledTwin twin = [] {
    DrumSceneSpec spec;
    spec.slab_depth = 18e-3;
    DrumScene drum(twin_settings(), spec);
    std::ostringstream log;
    drum.fill(log);
    std::cerr << log.str();
    return FilledTwin{drum.engine().checkpoint(), drum.fill_report(), drum.fill_line()};
  }();
  return twin;
}

const DemCheckpoint& settled_twin() { return filled_twin().bed; }

// Deepest overlap of the bed, between particles (minimum image along the slab) and with the
// shell of radius `shell` [m].
double deepest_overlap(const DemCheckpoint& c, double shell) {
  const ParticleStore& p = c.particles;
  double deepest = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.position[i];
    deepest = std::max(deepest, std::hypot(x.x(), x.z()) + p.radius[i] - shell);
    for (std::size_t j = i + 1; j < p.size(); ++j)
      deepest = std::max(deepest, p.radius[i] + p.radius[j] - c.box.minimum_image(x - p.position[j]).norm());
  }
  return deepest;
}

// The rain fill of the twin reaches the 50 % fill: it rained in more than the trim keeps (the
// bed rose above the fill line), settled below the seed's 1 mm/s, and after the trim the surface
// lies within a particle diameter below the fill line over the whole middle 80 % of the chord
// (no hollow) with a bed packed at 0.5-0.65; no two spheres and no sphere and the shell overlap
// by more than 5 % of R (a settled bed under its own weight, not a compressed placement).
TEST(DrumTwin, RainFillReachesTheFillLineSettledWithoutOverlaps) {
  const FilledTwin& t = filled_twin();
  const double r = 3e-3, R = 0.0725;
  EXPECT_TRUE(t.fill.target_reached);
  EXPECT_TRUE(t.fill.settled);
  EXPECT_LT(t.fill.final_max_speed, 1e-3);
  EXPECT_GT(t.fill.trimmed_count, 10u);
  EXPECT_EQ(t.fill.sunk_count, 0u);
  const ParticleStore& p = t.bed.particles;
  EXPECT_EQ(p.size() + t.fill.trimmed_count, t.fill.inserted_count);
  std::vector<SurfacePoint> section;
  for (const Vec3& x : p.position) section.push_back({x.x(), x.z()});
  const auto surface = bed_surface_points(section, r, R);
  int middle = 0;
  for (const SurfacePoint& s : surface)
    if (std::abs(s.x) < 0.8 * R) {
      ++middle;
      EXPECT_LE(s.z, t.fill_line + 1e-12) << "column at x = " << s.x;
      EXPECT_GT(s.z, t.fill_line - 2.0 * r) << "column at x = " << s.x;
    }
  EXPECT_GT(middle, 15);
  const double solid = static_cast<double>(p.size()) * 4.0 / 3.0 * std::numbers::pi * r * r * r /
                       (0.5 * std::numbers::pi * R * R * 18e-3);
  std::cerr << p.size() << " particles, solid fraction " << solid << ", deepest overlap "
            << deepest_overlap(t.bed, R) / r << " R\n";
  EXPECT_GT(solid, 0.5);
  EXPECT_LT(solid, 0.65);
  EXPECT_LT(deepest_overlap(t.bed, R), 0.05 * r);
}

DrumSteadyResult run_twin(double rpm) {
  DrumSceneSpec spec;
  spec.speed = rpm * 2.0 * std::numbers::pi / 60.0;
  spec.slab_depth = 18e-3;
  DrumScene drum(twin_settings(), spec, settled_twin());
  std::ostringstream log;
  drum.start_rotation(log);
  const double period = 60.0 / rpm;
  DrumAngleWatch watch(0.0725, std::max(0.3, 0.12 * period), 0.3, 1.5 * kDegree);
  while (!watch.converged() && watch.samples().size() < 150) {  // at most 3 s of rotation
    drum.engine().advance_to(drum.engine().time() + 0.02);
    watch.add(drum.sample());
  }
  const auto r = *watch.steady();
  std::cerr << rpm << " rpm: " << drum.engine().particles().size() << " particles, angle "
            << r.angle / kDegree << " +- " << r.angle_sd / kDegree << " deg, swing "
            << r.state.angle_swing / kDegree << " deg, bulge " << r.state.surface_bulge
            << ", airborne " << r.state.airborne_fraction << ", over top "
            << r.state.over_top_fraction << ", solid " << r.state.solid_body_fraction << ", shell "
            << r.state.shell_speed_ratio << ", to t = " << r.to
            << " s: " << classify_drum_bed(r.state).reason << '\n';
  return r;
}

// The seed's labels at 10 rpm (Fr = 0.008) and 50 rpm (Fr = 0.20): rolling, then cascading;
// the dynamic angle rises with the speed (seed Fig. 8) by more than the slow run's standard
// deviation of the sampled angle, and
// the slow angle is steeper than sliding friction alone allows (atan 0.5 = 26.6 deg; rolling
// resistance adds to it).
TEST(DrumTwin, RollsAt10RpmCascadesAt50RpmAngleRises) {
  const auto slow = run_twin(10);
  EXPECT_EQ(classify_drum_bed(slow.state).regime, DrumBedRegime::rolling);
  EXPECT_GT(slow.angle, 26.6 * kDegree);
  EXPECT_LT(slow.angle, 60 * kDegree);
  const auto fast = run_twin(50);
  EXPECT_EQ(classify_drum_bed(fast.state).regime, DrumBedRegime::cascading);
  EXPECT_GT(fast.angle, slow.angle + slow.angle_sd);
}

// The seed's label at 300 rpm (Fr = 7.3 > 1/sqrt(1 - f) = 1.41): the whole bed centrifuges.
TEST(DrumTwin, CentrifugesAt300Rpm) {
  EXPECT_EQ(classify_drum_bed(run_twin(300).state).regime, DrumBedRegime::centrifuging);
}

}  // namespace
}  // namespace feedflow
