#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>

#include "fullsim/dem/morton_order.hpp"
#include "fullsim/dem/neighbour_list.hpp"

namespace feedflow {
namespace {

using PairSet = std::set<std::pair<std::uint32_t, std::uint32_t>>;

// All id pairs closer than R_i + R_j + margin (minimum image), by brute force.
PairSet brute_force(const ParticleStore& p, const SimulationBox& box, double margin) {
  PairSet s;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double reach = p.radius[i] + p.radius[j] + margin;
      if (box.minimum_image(p.position[i] - p.position[j]).squaredNorm() < reach * reach)
        s.insert({std::min(p.id[i], p.id[j]), std::max(p.id[i], p.id[j])});
    }
  return s;
}

PairSet listed(const NeighbourList& list, const ParticleStore& p) {
  PairSet s;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::uint32_t e = list.first[i]; e < list.first[i + 1]; ++e) {
      const auto key = std::make_pair(p.id[i], p.id[list.partner[e]]);
      EXPECT_LT(key.first, key.second);  // listed once, under the smaller id
      EXPECT_TRUE(s.insert(key).second) << "pair listed twice";
    }
  return s;
}

struct Cloud {
  ParticleStore particles;
  SimulationBox box;
};

Cloud random_cloud(std::size_t n) {
  Cloud c;
  c.box.lower = Vec3(0, 0, 0);
  c.box.upper = Vec3(0.03, 0.02, 0.025);
  c.box.periodic = {true, false, true};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 x(0.03 * u(rng), 0.02 * u(rng), 0.025 * u(rng));
    c.particles.add(x, 1e-3 + 0.5e-3 * u(rng), 400.0);
  }
  return c;
}

// The half list holds exactly the pairs within R_i + R_j + skin that brute force finds, with a
// periodic x and z, before and after a Morton re-sort.
TEST(NeighbourList, FindsExactlyTheBruteForcePairsBeforeAndAfterSorting) {
  Cloud c = random_cloud(600);
  const double skin = 0.4e-3;
  NeighbourList list(skin, 3);
  list.rebuild(c.particles, c.box);
  const PairSet expected = brute_force(c.particles, c.box, skin);
  EXPECT_GT(expected.size(), 300u);
  EXPECT_EQ(listed(list, c.particles), expected);

  c.particles.permute(morton_order(c.particles.position, c.box, 4e-3));
  list.rebuild(c.particles, c.box);
  EXPECT_EQ(listed(list, c.particles), expected);
}

// After moves smaller than skin/2 (no rebuild) every touching pair is still listed; the
// rebuild then finds exactly the brute-force pairs again, and the history of each surviving
// pair is carried over to its new entry through sorting (matched by ids).
TEST(NeighbourList, CoversMovesWithinTheSkinAndCarriesHistoryByIds) {
  Cloud c = random_cloud(600);
  const double skin = 0.4e-3;
  NeighbourList list(skin, 3);
  list.rebuild(c.particles, c.box);
  // Tag each entry's history with its id pair.
  for (std::size_t i = 0; i < c.particles.size(); ++i)
    for (std::uint32_t e = list.first[i]; e < list.first[i + 1]; ++e) {
      list.history[3 * e] = c.particles.id[i];
      list.history[3 * e + 1] = c.particles.id[list.partner[e]];
      list.history[3 * e + 2] = 1.0;
    }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (auto& x : c.particles.position) {
    Vec3 d(u(rng), u(rng), u(rng));
    x += 0.49 * 0.5 * skin * d.normalized();
  }
  EXPECT_FALSE(list.needs_rebuild(c.particles));
  const PairSet listed_now = listed(list, c.particles);
  for (const auto& pair : brute_force(c.particles, c.box, 0.0))
    EXPECT_TRUE(listed_now.count(pair)) << pair.first << "-" << pair.second;

  c.particles.permute(morton_order(c.particles.position, c.box, 4e-3));
  list.rebuild(c.particles, c.box);
  EXPECT_EQ(listed(list, c.particles), brute_force(c.particles, c.box, skin));
  std::size_t carried = 0;
  for (std::size_t i = 0; i < c.particles.size(); ++i)
    for (std::uint32_t e = list.first[i]; e < list.first[i + 1]; ++e) {
      if (list.history[3 * e + 2] == 0.0) continue;  // a new pair
      ++carried;
      EXPECT_EQ(list.history[3 * e], c.particles.id[i]);
      EXPECT_EQ(list.history[3 * e + 1], c.particles.id[list.partner[e]]);
    }
  EXPECT_EQ(carried, list.carried_over());
  EXPECT_GT(carried, 300u);
}

}  // namespace
}  // namespace feedflow
