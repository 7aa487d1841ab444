#pragma once
// A small bed for the tests on ranks: 1 350 spheres dropped on a floor in a box periodic in x
// and y under tilted gravity, so grains slide across the rank cut and contacts carry history;
// and the positions of a run on any ranks, by particle id.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow::ranks_test {

using namespace dem_test;

inline DemSettings dropped_bed_settings(const DemRanks& ranks) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.1);
  s.ranks = ranks;
  s.gravity = Vec3(4.0, 0.0, -9.81);
  return s;
}

// The bed of dem_on_ranks_test.cpp, smaller: 1 350 spheres dropped on a floor in a periodic
// box under tilted gravity, so grains slide across the cut and contacts carry history.
inline DemEngine dropped_bed(const DemRanks& ranks) {
  const DemSettings s = dropped_bed_settings(ranks);
  ParticleStore p;
  add_lattice(p, Vec3(0.0016, 0.0016, 0.0016), 15, 15, 6, 0.0032, 0.05);
  const SimulationBox box{Vec3::Zero(), Vec3(15 * 0.0032, 15 * 0.0032, 0.03), {true, true, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  return e;
}

// The bed prepared (its plan not printed).
inline DemEngine prepared_bed(const DemRanks& ranks) {
  DemEngine e = dropped_bed(ranks);
  std::ostringstream plan;
  e.prepare(plan);
  return e;
}

// Every rank's own particles' positions by id (ids below n; NaN for an id no rank holds).
inline std::vector<Vec3> positions_by_id(const DemEngine& e, std::size_t n, const DemRanks& ranks) {
  std::vector<double> mine;
  const ParticleStore& p = e.particles();
  for (std::size_t k = 0; k < e.owned_count(); ++k)
    mine.insert(mine.end(), {static_cast<double>(p.id[k]), p.position[k].x(), p.position[k].y(),
                             p.position[k].z()});
  std::vector<Vec3> x(n, Vec3::Constant(std::nan("")));
  for (const auto& from : ranks.all_gather(mine))
    for (std::size_t k = 0; k < from.size(); k += 4)
      x[static_cast<std::size_t>(from[k])] = Vec3(from[k + 1], from[k + 2], from[k + 3]);
  return x;
}

// Across the periodic faces, the nearest image (a run wraps positions at its list rebuilds, and
// a restarted one rebuilds at the restart). An id present in one run only (NaN in the other:
// lost, or removed in one run only) counts as 1 m.
inline double largest_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b,
                                 const SimulationBox& box) {
  if (a.size() != b.size()) return 1.0;
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].hasNaN() != b[k].hasNaN()) return 1.0;
    if (!a[k].hasNaN()) worst = std::max(worst, box.minimum_image(a[k] - b[k]).norm());
  }
  return worst;
}

}  // namespace feedflow::ranks_test
