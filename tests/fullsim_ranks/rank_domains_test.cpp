#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "fullsim/dem/ranks/halo_exchange.hpp"
#include "fullsim/dem/ranks/rank_domains.hpp"

namespace feedflow {
namespace {

// Points spread unevenly over a box (denser towards its floor), the same on every rank; each
// rank takes every size-th one, as the engine does before the first cut.
std::vector<Vec3> my_share(const SimulationBox& box, std::size_t n, const DemRanks& ranks,
                           std::vector<std::uint32_t>* ids = nullptr) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> mine;
  for (std::size_t k = 0; k < n; ++k) {
    const double z = u(rng);
    const Vec3 x = box.lower + Vec3(u(rng), u(rng), z * z).cwiseProduct(box.length());
    if (static_cast<int>(k % static_cast<std::size_t>(ranks.size())) != ranks.rank()) continue;
    mine.push_back(x);
    if (ids) ids->push_back(static_cast<std::uint32_t>(k));
  }
  return mine;
}

// The cut gives every rank the same share of the particles (within one), every point of the
// box exactly one owner whose domain holds it, and the same domains on every rank.
TEST(RankDomains, BisectionBalancesTheCountAndTilesTheBox) {
  const DemRanks ranks = DemRanks::world();
  const SimulationBox box{Vec3(0, 0, 0), Vec3(0.2, 0.1, 0.3), {true, false, false}};
  const auto mine = my_share(box, 10001, ranks);
  const RankDomains d = RankDomains::bisect(mine, mine.size(), box, ranks);
  ASSERT_EQ(d.size(), ranks.size());
  std::vector<double> owned(static_cast<std::size_t>(ranks.size()), 0.0);
  for (const Vec3& x : mine) owned[static_cast<std::size_t>(d.owner(x))] += 1.0;
  ranks.sum(owned);
  const double share = 10001.0 / ranks.size();
  for (double c : owned) EXPECT_NEAR(c, share, 1.0);
  // Every point (also outside the box along the closed axes) in its owner's domain only.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 x = box.lower + Vec3(u(rng), u(rng), u(rng)).cwiseProduct(box.length());
    const int o = d.owner(x);
    EXPECT_EQ(d.distance2(box.wrap(x), o), 0.0);
  }
  std::vector<double> bounds;
  for (int r = 0; r < d.size(); ++r)
    for (int a = 0; a < 3; ++a)
      bounds.insert(bounds.end(), {d.domain(r).lower[a], d.domain(r).upper[a]});
  const auto all = ranks.all_gather(bounds);
  for (const auto& other : all) EXPECT_EQ(other, bounds);
}

// After migration every particle is owned by exactly one rank, the one whose domain holds it;
// after the ghost copy each rank holds every other rank's particle within reach of its own.
TEST(HaloExchange, EveryParticleOwnedOnceAndGhostsComplete) {
  const DemRanks ranks = DemRanks::world();
  const SimulationBox box{Vec3(0, 0, 0), Vec3(0.05, 0.04, 0.06), {true, true, false}};
  std::vector<std::uint32_t> ids;
  const auto mine = my_share(box, 4000, ranks, &ids);
  ParticleStore p;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    p.add(mine[k], 1e-3, 500.0);
    p.id.back() = ids[k];
  }
  const RankDomains d = RankDomains::bisect(p.position, p.size(), box, ranks);
  NeighbourList list(3e-4, 3);
  HaloExchange halo;
  halo.migrate(p, list, d, ranks);
  const double reach = 2e-3 + 3e-4;
  halo.build_ghosts(p, d, reach, ranks);
  ASSERT_EQ(halo.owned() + halo.ghosts(), p.size());

  std::vector<double> own_records;
  for (std::size_t k = 0; k < halo.owned(); ++k) {
    EXPECT_EQ(d.owner(p.position[k]), ranks.rank());
    own_records.insert(own_records.end(), {static_cast<double>(p.id[k]), p.position[k].x(),
                                           p.position[k].y(), p.position[k].z()});
  }
  const auto all = ranks.all_gather(own_records);
  std::vector<int> owners(4000, 0);
  for (const auto& from : all)
    for (std::size_t k = 0; k < from.size(); k += 4) ++owners[static_cast<std::size_t>(from[k])];
  EXPECT_TRUE(std::all_of(owners.begin(), owners.end(), [](int c) { return c == 1; }));

  std::vector<std::uint32_t> ghost_ids(p.id.begin() + static_cast<std::ptrdiff_t>(halo.owned()),
                                       p.id.end());
  std::sort(ghost_ids.begin(), ghost_ids.end());
  std::size_t needed = 0;
  for (int r = 0; r < ranks.size(); ++r) {
    if (r == ranks.rank()) continue;
    const auto& from = all[static_cast<std::size_t>(r)];
    for (std::size_t k = 0; k < from.size(); k += 4) {
      const Vec3 x(from[k + 1], from[k + 2], from[k + 3]);
      bool near = false;
      for (std::size_t i = 0; i < halo.owned() && !near; ++i)
        near = box.minimum_image(p.position[i] - x).norm() < reach;
      if (!near) continue;
      ++needed;
      EXPECT_TRUE(std::binary_search(ghost_ids.begin(), ghost_ids.end(),
                                     static_cast<std::uint32_t>(from[k])))
          << "particle " << from[k] << " of rank " << r << " is within reach but no ghost here";
    }
  }
  if (ranks.shared()) {
    EXPECT_GT(needed, 20u);  // the cut runs through the particles: many pairs cross it
  }
}

}  // namespace
}  // namespace feedflow
