#include <gtest/gtest.h>

#include <sstream>

#include "fullsim/dem/scene/rain_fill.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

// A 30 x 12 mm floor (periodic in y) and a rain region 20 mm above it; 150 spheres.
struct RainBox {
  DemEngine engine;
  RainFillSettings fill;
};

RainBox make_rain_box(std::uint64_t seed) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  const Vec3 lower(0, 0, 0), upper(0.03, 0.012, 0.06);
  RainBox b{DemEngine(s, SimulationBox{lower, upper, {false, true, false}}, ParticleStore{}), {}};
  b.engine.add_wall(Wall::plane("floor", lower, Vec3::UnitZ()));
  b.engine.add_wall(Wall::plane("x-", lower, Vec3::UnitX()));
  b.engine.add_wall(Wall::plane("x+", upper, -Vec3::UnitX()));
  RainFillSettings& f = b.fill;
  f.region_lower = Vec3(0.0, 0.0, 0.02);
  f.region_upper = Vec3(0.03, 0.012, 0.03);
  f.radius = kRadius;
  f.density = kDensity;
  const double m = kDensity * 4.0 / 3.0 * 3.14159265358979 * kRadius * kRadius * kRadius;
  f.mass_rate = 1500 * m;  // 150 spheres in 0.1 s
  f.target_count = 150;
  f.initial_velocity = Vec3(0, 0, -0.3);
  f.settle_speed = 5e-3;
  f.settle_time_cap = 0.3;
  f.trim_height = 0.006;
  f.band_height = 0.002;
  f.seed = seed;
  return b;
}

double deepest_overlap(const ParticleStore& p, const SimulationBox& box) {
  double deepest = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double d = box.minimum_image(p.position[i] - p.position[j]).norm();
      deepest = std::max(deepest, p.radius[i] + p.radius[j] - d);
    }
  return deepest;
}

// Every sphere is placed where it overlaps no particle (minimum image across the periodic
// axis) and no wall, inside the region, with the asked initial velocity.
TEST(RainFill, InsertsWithoutOverlapsInsideTheRegion) {
  RainBox b = make_rain_box(3);
  std::ostringstream log;
  b.fill.target_count = 60;  // one batch: nothing has moved yet when it is checked
  b.fill.mass_rate *= 100.0;
  b.fill.settle_time_cap = 0.0;
  b.fill.settle_check_interval = 1e-9;
  b.fill.trim_height.reset();
  rain_fill(b.engine, b.fill, log);
  const ParticleStore& p = b.engine.particles();
  ASSERT_EQ(p.size(), 60u);
  EXPECT_LE(deepest_overlap(p, b.engine.box()), 1e-6 * kRadius);
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_GE(p.position[k].z(), 0.02 - 1e-3);
    EXPECT_LE(p.position[k].z(), 0.03);
    EXPECT_GE(p.position[k].x(), kRadius);
    EXPECT_LE(p.position[k].x(), 0.03 - kRadius);
  }
}

// The whole fill (rain, settle, trim, bands) is deterministic for a seed and differs for
// another seed; mass is booked: kept + trimmed = inserted; bands follow the settled height.
TEST(RainFill, DeterministicForASeedAndBooksTheTrimmedMass) {
  std::ostringstream log;
  RainBox a = make_rain_box(11), b = make_rain_box(11), c = make_rain_box(12);
  const FillReport ra = rain_fill(a.engine, a.fill, log);
  const FillReport rb = rain_fill(b.engine, b.fill, log);
  rain_fill(c.engine, c.fill, log);
  ASSERT_EQ(ra.inserted_count, 150u);
  EXPECT_TRUE(ra.target_reached);
  EXPECT_GT(ra.trimmed_count, 0u);
  EXPECT_EQ(a.engine.particles().position, b.engine.particles().position);
  EXPECT_EQ(ra.trimmed_count, rb.trimmed_count);
  EXPECT_NE(a.engine.particles().position, c.engine.particles().position);
  EXPECT_NEAR(a.engine.particles().total_mass() + ra.trimmed_mass, ra.inserted_mass,
              1e-12 * ra.inserted_mass);
  const ParticleStore& p = a.engine.particles();
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_LE(p.position[k].z(), 0.006);
    EXPECT_EQ(p.layer[k], std::floor(p.position[k].z() / 0.002));
  }
  EXPECT_LT(deepest_overlap(p, a.engine.box()), 0.1 * kRadius);  // a settled bed, no blow-up
}

// A region that follows the fill rides above the resting particles.
TEST(RainFill, RestingFillTopIgnoresFallingParticles) {
  ParticleStore p;
  p.add(Vec3(0, 0, 0.01), kRadius, kDensity);
  p.add(Vec3(0, 0, 0.05), kRadius, kDensity, 0.0, Vec3(0, 0, -1.0));
  EXPECT_DOUBLE_EQ(resting_fill_top(p, 0.2), 0.01);
}

}  // namespace
}  // namespace feedflow
