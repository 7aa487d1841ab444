#pragma once
// Mass or funnel flow from the layer-coloured initial bands (seed 3.1: "first in, first out or
// not"). Criterion: the first-in-first-out index F is the fraction of particle pairs from
// different bands that leave in band order (the lower band first), over all such pairs;
// particles still in the domain at the end count as leaving after every discharged one (a
// stagnant zone left behind lowers F), pairs of two remaining particles are not counted.
// Ideal mass flow keeps the bands in order apart from the shear of the velocity profile
// (F -> 1); funnel flow drains the upper bands through a central channel before the material
// along the walls (F near 1/2 or below). Mass flow when F >= 0.8 (at least four pairs in five
// in order), funnel flow otherwise; the index is reported with the label.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace feedflow {

struct FlowOrder {
  double fifo_index = 0.0;     // F in [0, 1]
  double pairs = 0.0;          // pairs counted
  bool mass_flow = false;      // F >= threshold
  std::string label() const { return mass_flow ? "mass" : "funnel"; }
};

constexpr double kMassFlowFifoIndex = 0.8;

// `discharged_bands` in the order the particles left (ties in time may keep any order);
// `remaining_bands`: the bands of the particles still in the domain. Bands are integers.
FlowOrder flow_order(const std::vector<int>& discharged_bands, const std::vector<int>& remaining_bands,
                     double threshold = kMassFlowFifoIndex);
// The same with the particles still in the domain counted per band.
FlowOrder flow_order_by_counts(const std::vector<int>& discharged_bands, const std::map<int, double>& remaining_counts,
                               double threshold = kMassFlowFifoIndex);

}  // namespace feedflow
