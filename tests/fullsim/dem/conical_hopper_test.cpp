// The conical hopper in 3D (issue 22): its cone mesh, sector, fill and mass books.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "fullsim/dem/scene/conical_hopper.hpp"
#include "models/core/errors.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"
#include "tests/fullsim/dem/mass_books.hpp"

namespace feedflow {
namespace {

constexpr double kConeDegree = std::numbers::pi / 180.0;

// A small cone (30 deg, 60 mm outlet, 0.12 m bin, 0.12 m fill above the apex) of 3 mm
// spheres, as a sector of `sector_deg`.
ConicalHopper small_cone(double sector_deg) {
  return ConicalHopper{30.0 * kConeDegree, 0.06, 0.12, 0.12, sector_deg * kConeDegree, 3e-3};
}

// Every vertex of the cone mesh lies on the cone (radius D/2 + z tan theta) between the outlet
// and the transition, and the middle of every facet lies less than R/20 inside it (the facets
// are fine enough that a grain does not feel the faceting).
TEST(ConicalHopper, MeshLiesOnTheConeWithinATwentiethOfARadius) {
  const ConicalHopper h = small_cone(360.0);
  const MeshWall cone = h.cone_mesh();
  const TriangleMesh& m = cone.mesh();
  for (const Vec3& v : m.vertices) {
    EXPECT_GE(v.z(), -1e-15);
    EXPECT_LE(v.z(), h.bin_bottom() * (1 + 1e-12));
    EXPECT_NEAR(std::hypot(v.x(), v.y()), h.radius_at(v.z()), 1e-12);
  }
  double deepest = 0.0;
  for (const auto& t : m.triangles) {
    const Vec3 c = (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
    // inside the true cone, measured along its normal
    deepest = std::max(deepest, (h.radius_at(c.z()) - std::hypot(c.x(), c.y())) * std::cos(h.semi_angle));
  }
  EXPECT_GT(deepest, 0.0);
  EXPECT_LT(deepest, h.radius / 20.0);
}

// Geometry: the apex lies D/2 / tan(theta) below the outlet, the transition (B - D)/2 /
// tan(theta) above it; the fill mass is the frustum and the bin above it, the sector's share of
// it; a sector holds a point on its mid-line and refuses one beyond its sides.
TEST(ConicalHopper, GeometryFillMassAndSector) {
  const ConicalHopper whole = small_cone(360.0), quarter = small_cone(90.0);
  EXPECT_NEAR(whole.apex_depth(), 0.03 / std::tan(30 * kConeDegree), 1e-15);
  EXPECT_NEAR(whole.bin_bottom(), 0.03 / std::tan(30 * kConeDegree), 1e-15);
  const double zt = whole.fill_top(), zb = whole.bin_bottom();
  const double frustum = std::numbers::pi / 3.0 * zb * (0.03 * 0.03 + 0.03 * 0.06 + 0.06 * 0.06);
  const double volume = frustum + std::numbers::pi * 0.06 * 0.06 * (zt - zb);
  EXPECT_NEAR(whole.fill_mass(390.0, 0.6), volume * 390.0 * 0.6, 1e-12);
  EXPECT_NEAR(quarter.fill_mass(390.0, 0.6), 0.25 * whole.fill_mass(390.0, 0.6), 1e-15);
  EXPECT_TRUE(whole.whole());
  EXPECT_DOUBLE_EQ(quarter.share(), 0.25);
  const auto inside = quarter.admits();
  EXPECT_TRUE(inside(Vec3(0.04, 0.0, 0.05), 3e-3));
  EXPECT_FALSE(inside(Vec3(0.04, 0.039, 0.05), 3e-3));  // azimuth 44 deg: within R of side a
  EXPECT_FALSE(inside(Vec3(-0.01, 0.0, 0.05), 3e-3));   // behind the axis
  EXPECT_FALSE(inside(Vec3(0.045, 0.0, 0.01), 3e-3));   // outside the cone near the outlet
  EXPECT_TRUE(small_cone(360.0).admits()(Vec3(-0.01, 0.0, 0.05), 3e-3));
  // A sector wider than 90 deg (its sides would be half-planes) is refused, naming the key.
  try {
    small_cone(120.0).check();
    FAIL() << "a 120 deg sector was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "dem.sector_angle");
  }
  EXPECT_THROW(small_cone(10.0).check(), InputError);  // 2.6 mm wide at the outlet rim
}

// A quarter cone filled and discharging: every sphere stays in the sector and above the cone
// wall, and every inserted sphere is in the domain, through the sink or trimmed, exactly once.
TEST(ConicalHopper, QuarterFillsInsideAndKeepsItsBooks) {
  const ConicalHopper h = small_cone(90.0);
  DemEngine e(dem_test::pine_twin_settings(), h.box(), ParticleStore{});
  h.add_walls(e);
  std::ostringstream log;
  RainFillSettings rain = h.rain(390.0, 5, 7);
  rain.settle_time_cap = 0.1;
  const FillReport f = rain_fill(e, rain, log);
  const ParticleStore& p = e.particles();
  ASSERT_GT(p.size(), 300u);
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec3& x = p.position[k];
    EXPECT_LE(x.z(), h.fill_top());
    // 0.8 R from the true cone (along its normal): the facets stand up to 0.05 R inside it and
    // the 3D bed's weight presses the wall contacts to about 0.14 R
    const double from_cone = (h.radius_at(x.z()) - std::hypot(x.x(), x.y())) * std::cos(h.semi_angle);
    EXPECT_GT(from_cone, 0.8 * h.radius) << "particle " << p.id[k];
    EXPECT_GT(x.x() * std::sin(45 * kConeDegree) - std::abs(x.y()) * std::cos(45 * kConeDegree),
              0.9 * h.radius);
  }
  e.set_wall_removal_time("gate", e.time());
  e.advance_to(e.time() + 0.25);
  ASSERT_GT(e.outlet_sink()->removed_count(), 30u);  // it discharged
  dem_test::expect_mass_books_balance(e, f);
}

}  // namespace
}  // namespace feedflow
