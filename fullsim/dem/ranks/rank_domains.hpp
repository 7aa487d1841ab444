#pragma once
// The sub-boxes a DEM run's box is cut into, one per rank, by recursive coordinate bisection
// on the particle count (each cut across the longest side of its box, where the particles of
// the box divide in the ratio of the ranks on either side), so every rank owns about as many
// particles. A rank owns the particles whose centre lies in its sub-box; along an axis that is
// not periodic the sub-boxes at the box's faces reach on to infinity, so a particle that left
// the box (held by a wall, or falling to the outlet sink) still has an owner.
//
//   RankDomains d = RankDomains::bisect(particles.position, owned, box, ranks);
//   int owner = d.owner(x);
#include <vector>

#include "fullsim/dem/ranks/dem_ranks.hpp"
#include "fullsim/dem/simulation_box.hpp"

namespace feedflow {

struct RankBox {
  Vec3 lower = Vec3::Zero();  // [m] (may be -infinity along an axis that is not periodic)
  Vec3 upper = Vec3::Zero();  // [m] (may be +infinity)
};

class RankDomains {
 public:
  // One domain: everything.
  explicit RankDomains(const SimulationBox& box = {});
  // The bisection of `box` among the ranks by the first `count` of each rank's positions
  // (collective: every rank calls it; all get the same domains, bit for bit).
  static RankDomains bisect(const std::vector<Vec3>& positions, std::size_t count,
                            const SimulationBox& box, const DemRanks& ranks);

  int size() const { return static_cast<int>(boxes_.size()); }
  const RankBox& domain(int rank) const { return boxes_[static_cast<std::size_t>(rank)]; }
  // The rank whose domain holds x (along periodic axes x is taken as wrapped into the box).
  int owner(const Vec3& x) const;
  // The squared distance from x to a rank's domain, the shortest image along periodic axes.
  double distance2(const Vec3& x, int rank) const;
  // The other ranks whose domains come within `reach` of this rank's (shortest image).
  std::vector<int> neighbours(int rank, double reach) const;

 private:
  struct Node {
    int axis = -1;    // -1: a leaf
    double at = 0.0;  // the cut: below goes left
    int left = -1, right = -1;
    int rank = 0;  // a leaf's rank
  };
  SimulationBox box_;
  std::vector<Node> nodes_;
  std::vector<RankBox> boxes_;
};

}  // namespace feedflow
