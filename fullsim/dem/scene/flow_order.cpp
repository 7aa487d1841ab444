#include "fullsim/dem/scene/flow_order.hpp"

#include <map>

namespace feedflow {

FlowOrder flow_order(const std::vector<int>& discharged, const std::vector<int>& remaining,
                     double threshold) {
  std::map<int, double> rest;
  for (int band : remaining) rest[band] += 1.0;
  return flow_order_by_counts(discharged, rest, threshold);
}

FlowOrder flow_order_by_counts(const std::vector<int>& discharged, const std::map<int, double>& rest,
                               double threshold) {
  // Walk the exits in order: each particle leaving now forms a pair with every particle that
  // left before it; the pair is in order when the earlier one's band is lower. Counts per band
  // make this O(N log B).
  std::map<int, double> left_before;  // band -> how many have left so far
  double total_before = 0.0, in_order = 0.0, pairs = 0.0;
  auto add_pairs = [&](int band, double weight) {
    double lower = 0.0, same = 0.0;
    for (const auto& [b, count] : left_before) {
      if (b < band) lower += count;
      else if (b == band) same = count;
      else break;
    }
    in_order += weight * lower;
    pairs += weight * (total_before - same);
  };
  for (int band : discharged) {
    add_pairs(band, 1.0);
    left_before[band] += 1.0;
    total_before += 1.0;
  }
  for (const auto& [band, count] : rest) add_pairs(band, count);
  FlowOrder f;
  f.pairs = pairs;
  f.fifo_index = pairs > 0.0 ? in_order / pairs : 1.0;
  f.mass_flow = f.fifo_index >= threshold;
  return f;
}

}  // namespace feedflow
