#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

// A particle's state by id, gathered from every rank's own particles.
struct Gathered {
  std::vector<Vec3> position, velocity, angular_velocity;
  std::vector<int> owner;
};

Gathered gather(const DemEngine& e, std::size_t count, const DemRanks& ranks) {
  std::vector<double> mine;
  const ParticleStore& p = e.particles();
  for (std::size_t k = 0; k < e.owned_count(); ++k) {
    mine.push_back(p.id[k]);
    for (const Vec3* v : {&p.position[k], &p.velocity[k], &p.angular_velocity[k]})
      mine.insert(mine.end(), {v->x(), v->y(), v->z()});
  }
  Gathered g;
  g.position.assign(count, Vec3::Constant(std::nan("")));
  g.velocity = g.angular_velocity = g.position;
  g.owner.assign(count, -1);
  const auto all = ranks.all_gather(mine);
  for (std::size_t r = 0; r < all.size(); ++r)
    for (std::size_t k = 0; k < all[r].size(); k += 10) {
      const auto id = static_cast<std::size_t>(all[r][k]);
      EXPECT_EQ(g.owner[id], -1) << "particle " << id << " owned twice";
      g.owner[id] = static_cast<int>(r);
      g.position[id] = Vec3(all[r][k + 1], all[r][k + 2], all[r][k + 3]);
      g.velocity[id] = Vec3(all[r][k + 4], all[r][k + 5], all[r][k + 6]);
      g.angular_velocity[id] = Vec3(all[r][k + 7], all[r][k + 8], all[r][k + 9]);
    }
  return g;
}

// A bed of 2 700 spheres dropped on a floor in a periodic box under tilted gravity (1 500
// steps, 2 300 contacts): on the ranks it holds the same grains with the same kinetic energy
// and contact count as on one, positions to round-off, and two runs on the same ranks give
// the same bits.
struct DroppedBed {
  DemEngine engine(const DemRanks& ranks) const {
    DemSettings s = hertz_settings(0.3, 0.5, 0.1);
    s.ranks = ranks;
    s.gravity = Vec3(4.0, 0.0, -9.81);  // tilted: the bed also slides along x
    ParticleStore p;
    add_lattice(p, Vec3(0.0016, 0.0016, 0.0016), 15, 15, 12, 0.0032, 0.05);
    const SimulationBox box{
        Vec3::Zero(), Vec3(15 * 0.0032, 15 * 0.0032, 0.04), {true, true, false}};
    DemEngine e(s, box, p);
    e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
    return e;
  }
};

std::size_t touching_pairs(const DemEngine& e, const Gathered& g) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < g.position.size(); ++i)
    for (std::size_t j = i + 1; j < g.position.size(); ++j)
      n += e.box().minimum_image(g.position[i] - g.position[j]).norm() < 2 * kRadius;
  return n;
}

TEST(DemOnRanks, DroppedBedMatchesOneRankToRoundOff) {
  const DemRanks ranks = DemRanks::world();
  const DroppedBed scene;
  DemEngine alone = scene.engine(DemRanks::one());
  DemEngine shared = scene.engine(ranks);
  DemEngine again = scene.engine(ranks);
  std::ostringstream plan;
  alone.prepare(plan);
  shared.prepare(plan);
  again.prepare(plan);
  // Round-off grows tenfold every 50 steps or so once the grains collide (1.3e-13 m at step
  // 1 500): compared while it is still round-off.
  const long steps = 1500;
  alone.run_steps(steps);
  shared.run_steps(steps);
  again.run_steps(steps);
  const std::size_t n = alone.particles().size();
  EXPECT_EQ(shared.global_count(), n);
  const Gathered g = gather(shared, n, ranks), h = gather(again, n, ranks);
  const double e1 = alone.kinetic_energy(), e2 = shared.kinetic_energy();
  Gathered a;
  a.position.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    a.position[alone.particles().id[k]] = alone.particles().position[k];
  double worst = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    worst = std::max(worst, (g.position[k] - a.position[k]).norm());
  const std::size_t c1 = touching_pairs(alone, a), c2 = touching_pairs(shared, g);
  if (ranks.rank() == 0)
    std::printf("bed: KE %.6g / %.6g J, touching %zu / %zu, largest position difference %.3g m\n",
                e1, e2, c1, c2, worst);
  EXPECT_GT(c1, 2000u);  // a bed forming, not a gas
  EXPECT_NEAR(e2, e1, 1e-9 * e1);
  EXPECT_EQ(c1, c2);
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(g.position, h.position);  // same ranks, same bits
  EXPECT_EQ(g.angular_velocity, h.angular_velocity);
}

// The contacts with history of a run: id pair -> history, gathered from every rank, and how
// many ranks list each.
std::map<std::uint64_t, std::vector<double>> loaded_contacts(const DemEngine& e,
                                                             const DemRanks& ranks,
                                                             std::map<std::uint64_t, int>* listed) {
  const NeighbourList& l = e.neighbours();
  const std::size_t h = l.history_size();
  std::vector<double> mine;
  for (std::size_t k = 0; k < l.entry_keys().size(); ++k) {
    const double* v = l.history.data() + k * h;
    if (std::all_of(v, v + h, [](double x) { return x == 0.0; })) continue;
    mine.push_back(static_cast<double>(l.entry_keys()[k]));
    mine.insert(mine.end(), v, v + h);
  }
  std::map<std::uint64_t, std::vector<double>> all;
  for (const auto& from : ranks.all_gather(mine))
    for (std::size_t k = 0; k < from.size(); k += h + 1) {
      const auto key = static_cast<std::uint64_t>(from[k]);
      all[key].assign(from.begin() + static_cast<std::ptrdiff_t>(k + 1),
                      from.begin() + static_cast<std::ptrdiff_t>(k + 1 + h));
      if (listed) ++(*listed)[key];
    }
  return all;
}

// The same bed: the cut is across x (periodic), so sliding grains cross it, and the box's
// periodic face, in contact with others. Every loaded contact is listed on one rank only, with the
// history of the one-rank run to round-off, including those whose listing grain changed rank.
TEST(DemOnRanks, ContactHistoryFollowsGrainsAcrossTheCut) {
  const DemRanks ranks = DemRanks::world();
  const DroppedBed scene;
  DemEngine alone = scene.engine(DemRanks::one());
  DemEngine shared = scene.engine(ranks);
  std::ostringstream plan;
  alone.prepare(plan);
  shared.prepare(plan);
  const std::size_t n = alone.particles().size();
  const Gathered before = gather(shared, n, ranks);
  alone.run_steps(1500);
  shared.run_steps(1500);
  const Gathered after = gather(shared, n, ranks);
  std::map<std::uint64_t, int> listed;
  const auto one = loaded_contacts(alone, DemRanks::one(), nullptr);
  const auto many = loaded_contacts(shared, ranks, &listed);
  EXPECT_EQ(many.size(), one.size());
  std::size_t moved = 0;
  double worst = 0.0, scale = 0.0;
  for (const auto& [key, h] : one) {
    auto it = many.find(key);
    ASSERT_NE(it, many.end()) << "contact " << (key >> 32) << "-" << (key & 0xffffffffu) << " lost";
    EXPECT_EQ(listed[key], 1);
    for (std::size_t q = 0; q < h.size(); ++q) {
      worst = std::max(worst, std::abs(it->second[q] - h[q]));
      scale = std::max(scale, std::abs(h[q]));
    }
    const auto first = static_cast<std::size_t>(key >> 32);
    moved += before.owner[first] != after.owner[first];
  }
  if (ranks.rank() == 0)
    std::printf(
        "contacts: %zu loaded, %zu listed by a grain that changed rank; largest history "
        "difference %.3g (largest history %.3g)\n",
        one.size(), moved, worst, scale);
  EXPECT_GT(one.size(), 1000u);
  EXPECT_LT(worst, 1e-9 * scale);
  if (ranks.shared()) {
    EXPECT_GT(moved, 10u);  // contacts did change rank with their grain
  }
}

}  // namespace
}  // namespace feedflow
