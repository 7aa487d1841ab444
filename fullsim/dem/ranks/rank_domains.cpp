#include "fullsim/dem/ranks/rank_domains.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace feedflow {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Enough halvings of a box side to reach the last bit of its coordinates.
constexpr int kCutHalvings = 60;

// The distance from x to [lo, hi] along one axis; along a periodic axis of length `period` the
// shortest over x's images.
double axis_gap(double x, double lo, double hi, double period) {
  auto gap = [&](double y) { return y < lo ? lo - y : (y > hi ? y - hi : 0.0); };
  if (period <= 0.0) return gap(x);
  return std::min({gap(x), gap(x - period), gap(x + period)});
}

// A group of ranks [first, last) still to be cut, its box and its node.
struct Group {
  int first = 0, last = 1;
  Vec3 lower, upper;
  int node = 0;
};

}  // namespace

RankDomains::RankDomains(const SimulationBox& box) : box_(box) {
  nodes_.push_back({});
  RankBox all{box.lower, box.upper};
  for (int a = 0; a < 3; ++a)
    if (!box.periodic[a]) {
      all.lower[a] = -kInfinity;
      all.upper[a] = kInfinity;
    }
  boxes_.push_back(all);
}

RankDomains RankDomains::bisect(const std::vector<Vec3>& positions, std::size_t count,
                                const SimulationBox& box, const DemRanks& ranks) {
  RankDomains d(box);
  const int n = ranks.size();
  d.boxes_.assign(static_cast<std::size_t>(n), RankBox{});
  // Each particle's coordinates clamped (or wrapped) into the box, and the group it is in.
  std::vector<Vec3> x(count);
  for (std::size_t k = 0; k < count; ++k) {
    x[k] = box.wrap(positions[k]);
    for (int a = 0; a < 3; ++a) x[k][a] = std::clamp(x[k][a], box.lower[a], box.upper[a]);
  }
  std::vector<int> group_of(count, 0);
  std::vector<Group> groups{{0, n, box.lower, box.upper, 0}};
  while (true) {
    std::vector<int> cutting;
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (groups[g].last - groups[g].first > 1) cutting.push_back(static_cast<int>(g));
    if (cutting.empty()) break;
    // Per cut group: its particle count, then halve its cut interval until the count below
    // the cut meets the share of the left ranks.
    std::vector<int> axis(groups.size(), 0);
    std::vector<double> lo(groups.size()), hi(groups.size()), total(groups.size(), 0.0);
    for (int g : cutting) {
      const Vec3 side = groups[g].upper - groups[g].lower;
      int a = 0;
      for (int b = 1; b < 3; ++b)
        if (side[b] > side[a]) a = b;
      axis[g] = a;
      lo[g] = groups[g].lower[a];
      hi[g] = groups[g].upper[a];
    }
    for (std::size_t k = 0; k < count; ++k) total[static_cast<std::size_t>(group_of[k])] += 1.0;
    ranks.sum(total);
    for (int h = 0; h < kCutHalvings; ++h) {
      std::vector<double> below(groups.size(), 0.0);
      for (std::size_t k = 0; k < count; ++k) {
        const auto g = static_cast<std::size_t>(group_of[k]);
        if (x[k][axis[g]] < 0.5 * (lo[g] + hi[g])) below[g] += 1.0;
      }
      ranks.sum(below);
      for (int g : cutting) {
        const Group& gr = groups[static_cast<std::size_t>(g)];
        const int left_ranks = (gr.last - gr.first) / 2;
        const double target = total[g] * left_ranks / (gr.last - gr.first);
        const double mid = 0.5 * (lo[g] + hi[g]);
        if (below[g] < target)
          lo[g] = mid;
        else
          hi[g] = mid;
      }
    }
    // Split the groups: left keeps the first half of the ranks.
    std::vector<Group> next;
    std::vector<int> new_index(groups.size() * 2, -1);
    for (std::size_t g = 0; g < groups.size(); ++g) {
      Group gr = groups[g];
      if (gr.last - gr.first == 1) {
        new_index[2 * g] = static_cast<int>(next.size());
        next.push_back(gr);
        continue;
      }
      const int a = axis[g];
      const double at = 0.5 * (lo[g] + hi[g]);
      const int middle = gr.first + (gr.last - gr.first) / 2;
      Node& node = d.nodes_[static_cast<std::size_t>(gr.node)];
      node.axis = a;
      node.at = at;
      node.left = static_cast<int>(d.nodes_.size());
      node.right = node.left + 1;
      const int left_node = node.left, right_node = node.right;
      d.nodes_.push_back({});
      d.nodes_.push_back({});
      Group left = gr, right = gr;
      left.last = middle;
      left.upper[a] = at;
      left.node = left_node;
      right.first = middle;
      right.lower[a] = at;
      right.node = right_node;
      new_index[2 * g] = static_cast<int>(next.size());
      next.push_back(left);
      new_index[2 * g + 1] = static_cast<int>(next.size());
      next.push_back(right);
    }
    for (std::size_t k = 0; k < count; ++k) {
      const auto g = static_cast<std::size_t>(group_of[k]);
      const bool right = groups[g].last - groups[g].first > 1 &&
                         !(x[k][axis[g]] < d.nodes_[static_cast<std::size_t>(groups[g].node)].at);
      group_of[k] = new_index[2 * g + (right ? 1 : 0)];
    }
    groups = std::move(next);
  }
  for (const Group& g : groups) {
    d.nodes_[static_cast<std::size_t>(g.node)].rank = g.first;
    RankBox b{g.lower, g.upper};
    for (int a = 0; a < 3; ++a) {
      if (box.periodic[a]) continue;
      if (b.lower[a] <= box.lower[a]) b.lower[a] = -kInfinity;
      if (b.upper[a] >= box.upper[a]) b.upper[a] = kInfinity;
    }
    d.boxes_[static_cast<std::size_t>(g.first)] = b;
  }
  return d;
}

int RankDomains::owner(const Vec3& x) const {
  const Vec3 y = box_.wrap(x);
  std::size_t k = 0;
  while (nodes_[k].axis >= 0)
    k = static_cast<std::size_t>(y[nodes_[k].axis] < nodes_[k].at ? nodes_[k].left
                                                                  : nodes_[k].right);
  return nodes_[k].rank;
}

double RankDomains::distance2(const Vec3& x, int rank) const {
  const RankBox& b = domain(rank);
  double d2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double g = axis_gap(x[a], b.lower[a], b.upper[a],
                              box_.periodic[a] ? box_.upper[a] - box_.lower[a] : 0.0);
    d2 += g * g;
  }
  return d2;
}

std::vector<int> RankDomains::neighbours(int rank, double reach) const {
  std::vector<int> near;
  const RankBox& mine = domain(rank);
  for (int s = 0; s < size(); ++s) {
    if (s == rank) continue;
    const RankBox& other = domain(s);
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double period = box_.periodic[a] ? box_.upper[a] - box_.lower[a] : 0.0;
      // The gap between two intervals: that of one's nearer end to the other.
      double g = std::min(axis_gap(other.lower[a], mine.lower[a], mine.upper[a], period),
                          axis_gap(other.upper[a], mine.lower[a], mine.upper[a], period));
      if (other.lower[a] <= mine.upper[a] && other.upper[a] >= mine.lower[a]) g = 0.0;
      d2 += g * g;
    }
    if (d2 <= reach * reach) near.push_back(s);
  }
  return near;
}

}  // namespace feedflow
