// The wall loop skips the walls a particle cannot reach before the next neighbour rebuild
// (fullsim/dem/wall_reach.hpp): which walls are kept, and that a skipped wall never hides a
// contact or a history.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <sstream>

#include "fullsim/dem/mesh_wall.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

// A rectangle [x0, x1] x [y0, y1] at height z as two triangles, tilted by `slope` (dz/dx).
MeshWall ramp(const std::string& name, double x0, double x1, double y0, double y1, double z,
              double slope) {
  TriangleMesh m;
  const Vec3 a(x0, y0, z + slope * x0), b(x1, y0, z + slope * x1), c(x1, y1, z + slope * x1),
      d(x0, y1, z + slope * x0);
  m.add_triangle(a, b, c, 0);
  m.add_triangle(a, c, d, 1);
  m.source = "test";
  return MeshWall(name, std::move(m));
}

// Kept: a plane or a mesh within radius + margin of the centre, and a moving wall wherever it
// is; dropped: still walls farther away (bit k: plane k, then the meshes).
TEST(WallReach, KeepsTheWallsWithinTheRadiusAndTheMargin) {
  ParticleStore p;
  const double r = kRadius, margin = 0.3 * r;
  p.add(Vec3(0.0, 0.0, r + 0.9 * margin), r, kDensity, 0, Vec3::Zero());  // near the floor
  p.add(Vec3(0.0, 0.0, r + 1.1 * margin), r, kDensity, 0, Vec3::Zero());  // just beyond
  p.add(Vec3(0.0, 0.0, 0.02), r, kDensity, 0, Vec3::Zero());              // near the mesh
  std::vector<Wall> walls{Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()),
                          Wall::plane("far side", Vec3(0.5, 0, 0), -Vec3::UnitX())};
  std::vector<MeshWall> meshes{
      ramp("roof", -0.01, 0.01, -0.01, 0.01, 0.02 + r + 0.5 * margin, 0.0)};
  WallReach reach;
  reach.update(p, walls, meshes, margin);
  EXPECT_EQ(reach.mask(0), 0b001u);
  EXPECT_EQ(reach.mask(1), 0b000u);
  EXPECT_EQ(reach.mask(2), 0b100u);
  EXPECT_NEAR(reach.share_in_reach(), 2.0 / 9.0, 1e-15);
  walls[1].moving(Vec3(0.1, 0, 0), Vec3::Zero());  // a moving wall is always tested
  reach.update(p, walls, meshes, margin);
  EXPECT_EQ(reach.mask(1), 0b010u);
}

// Spheres with the seed's law (a history per wall contact) rain into a V of two mesh ramps
// between side planes and come to rest: at every step, a wall the mask skips for a particle
// neither touches it nor holds a history for it, so skipping it changes nothing; and the mask
// does skip most particle-wall pairs, so the test has something to check.
TEST(WallReach, ASkippedWallHoldsNoContactAndNoHistory) {
  DemSettings s = hertz_settings(0.5, 0.5, 0.1);
  s.law = choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "none");
  ParticleStore p;
  add_lattice(p, Vec3(-0.0096, 0.002, 0.009), 7, 3, 5, 3.2e-3, 0.05);
  const Vec3 lower(-0.02, 0.0, -0.01), upper(0.02, 0.012, 0.06);
  SimulationBox box{
      lower - Vec3::Constant(0.01), upper + Vec3::Constant(0.01), {false, false, false}};
  DemEngine e(s, box, p);
  add_side_walls(e, lower, upper);
  e.add_mesh_wall(ramp("left", -0.02, 0.0, -0.001, 0.013, 0.0, -0.6));
  e.add_mesh_wall(ramp("right", 0.0, 0.02, -0.001, 0.013, 0.0, 0.6));
  std::ostringstream plan;
  e.prepare(plan);
  const std::size_t walls = e.walls().size(), meshes = e.mesh_walls().size();
  // stride = walls x history + meshes x kMaxContacts x (3 + history)
  const std::size_t slots = meshes * MeshWall::kMaxContacts;
  const std::size_t per_wall = (e.particles().wall_history_stride() - 3 * slots) / (walls + slots);
  ASSERT_GT(per_wall, 0u);
  std::size_t skipped = 0, tested = 0, touching = 0;
  const int steps = static_cast<int>(0.02 / e.time_step());  // 20 ms: falls, bounces, piles
  for (int step = 0; step < steps; ++step) {
    e.run_steps(1);
    const ParticleStore& q = e.particles();
    const std::size_t stride = q.wall_history_stride();
    for (std::size_t i = 0; i < q.size(); ++i) {
      const std::uint64_t mask = e.wall_reach().mask(i);
      for (std::size_t k = 0; k < walls; ++k) {
        const bool in = (mask >> k) & 1u;
        const bool touches = e.walls()[k].touch(q.position[i]).gap < q.radius[i];
        (in ? tested : skipped) += 1;
        touching += touches;
        if (in) continue;
        ASSERT_FALSE(touches) << "particle " << i << " wall " << k << " step " << step;
        for (std::size_t h = 0; h < per_wall; ++h)
          ASSERT_EQ(q.wall_history[i * stride + k * per_wall + h], 0.0);
      }
      for (std::size_t m = 0; m < meshes; ++m) {
        const bool in = (mask >> (walls + m)) & 1u;
        std::array<MeshTouch, MeshWall::kMaxContacts> t;
        const bool touches = e.mesh_walls()[m].touches(q.position[i], q.radius[i], t) > 0;
        (in ? tested : skipped) += 1;
        touching += touches;
        if (in) continue;
        ASSERT_FALSE(touches) << "particle " << i << " mesh " << m << " step " << step;
        const double* slots = &q.wall_history[i * stride + walls * per_wall];
        const std::size_t slot_doubles = MeshWall::kMaxContacts * (3 + per_wall);
        for (std::size_t h = m * slot_doubles; h < (m + 1) * slot_doubles; ++h)
          ASSERT_EQ(slots[h], 0.0);
      }
    }
  }
  std::printf("particle-wall pairs over %d steps: %zu skipped, %zu tested, %zu touching\n", steps,
              skipped, tested, touching);
  EXPECT_GT(skipped, 2 * tested);
  EXPECT_GT(touching, 0u);
}

}  // namespace
}  // namespace feedflow
