#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "fullsim/dem/bed_view.hpp"
#include "fullsim/dem/ranks/gathered_particles.hpp"
#include "fullsim/dem/scene/deposit_profile.hpp"
#include "fullsim/dem/scene/drum_free_surface.hpp"
#include "fullsim/dem/scene/rain_fill.hpp"
#include "fullsim/dem/scene/speed_profile.hpp"
#include "tests/fullsim_ranks/ranks_test_bed.hpp"

namespace feedflow {
namespace {

using namespace ranks_test;

// The k largest of every rank's values per bin are the k largest of their union: each rank
// offers 3 bins of values that interleave with the other ranks' (rank r holds r, r + n, ...).
TEST(BedViewOnRanks, HighestPerBinIsTheUnionsHighest) {
  const DemRanks ranks = DemRanks::world();
  const int n = ranks.size();
  constexpr std::size_t k = 5, bins = 3;
  std::vector<double> tops(bins * k, -std::numeric_limits<double>::infinity());
  for (std::size_t b = 0; b < bins; ++b) {
    std::vector<double> mine;
    for (int v = ranks.rank(); v < 12; v += n) mine.push_back(100.0 * b + v);
    if (b == 2) mine.resize(1);  // fewer than k on every rank: the rest stays padding
    std::sort(mine.begin(), mine.end(), std::greater<>());
    std::copy_n(mine.begin(), std::min(k, mine.size()), tops.begin() + static_cast<long>(b * k));
  }
  ranks.highest(tops, k);
  for (std::size_t b = 0; b < 2; ++b)
    for (std::size_t j = 0; j < k; ++j) EXPECT_EQ(tops[b * k + j], 100.0 * b + 11 - j);
  // bin 2: each rank's lowest value, 0 .. n-1, then padding
  for (std::size_t j = 0; j < k; ++j)
    EXPECT_EQ(tops[2 * k + j], j < static_cast<std::size_t>(std::min(n, 12))
                                   ? 200.0 + (std::min(n, 12) - 1 - static_cast<int>(j))
                                   : -std::numeric_limits<double>::infinity());
}

// What a scene measures from its own particles and the view's reductions is what the gathered
// whole bed gives: counts, masses, energy, the speed profile, deposit heights, the resting
// top and the drum's surface points, on a bed moving across the rank cut.
TEST(BedViewOnRanks, ReductionsMeasureWhatTheGatheredBedDoes) {
  const DemRanks ranks = DemRanks::world();
  DemEngine e = prepared_bed(ranks);
  e.run_steps(1500);
  const BedView view = e.bed();
  const ParticleStore whole_store = all_gather_particles(e.particles(), e.owned_count(), ranks);
  const BedView whole(whole_store, whole_store.size(), DemRanks::one());
  if (ranks.shared()) {
    EXPECT_GT(view.own(), 0u);
    EXPECT_LT(static_cast<double>(view.own()), view.count());
  }
  EXPECT_EQ(view.count(), 1350.0);
  EXPECT_NEAR(view.total_mass(), whole.total_mass(), 1e-12 * whole.total_mass());  // sums in another order
  EXPECT_NEAR(view.kinetic_energy(), whole.kinetic_energy(), 1e-12 * whole.kinetic_energy());
  EXPECT_GT(whole.kinetic_energy(), 0.0);

  const double r = 0.0016;
  const SpeedProfile a = speed_profile(view, 0.006, 2 * r, 2 * r), b = speed_profile(whole, 0.006, 2 * r, 2 * r);
  ASSERT_EQ(a.offset, b.offset);
  ASSERT_GT(a.offset.size(), 3u);
  for (std::size_t i = 0; i < a.speed.size(); ++i) EXPECT_NEAR(a.speed[i], b.speed[i], 1e-12 * b.speed[i]);

  const DepositProfile d = measure_deposit(view, 0.048, 0.0, 2 * r),
                       w = measure_deposit(whole, 0.048, 0.0, 2 * r);
  EXPECT_EQ(d.height, w.height);
  EXPECT_EQ(d.front, w.front);
  EXPECT_GT(w.mid_ramp.value, 0.0);

  EXPECT_EQ(resting_fill_top(view, 0.05), resting_fill_top(whole, 0.05));
  EXPECT_EQ(resting_fill_top(view, 1e-9), resting_fill_top(whole, 1e-9));

  // The bed's cross-section as a drum's, centred (radius large enough to keep every column).
  auto section = [](const ParticleStore& p, std::size_t n) {
    std::vector<SurfacePoint> s(n);
    for (std::size_t i = 0; i < n; ++i) s[i] = {p.position[i].x() - 0.024, p.position[i].z() - 0.02};
    return s;
  };
  const auto mine = bed_surface_points(section(e.particles(), view.own()), r, 0.1, [&view](ColumnTops& t) {
    view.highest(t.z, t.depth);
    view.sum(t.count);
  });
  const auto all = bed_surface_points(section(whole_store, whole_store.size()), r, 0.1);
  ASSERT_EQ(mine.size(), all.size());
  ASSERT_GE(all.size(), 10u);
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(mine[i].x, all[i].x);
    EXPECT_EQ(mine[i].z, all[i].z);
  }
}

}  // namespace
}  // namespace feedflow
