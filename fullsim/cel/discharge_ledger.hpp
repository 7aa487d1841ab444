#pragma once
// The book of the mass that left the grid through outflow faces (models.md 2.7 (a), exact mass
// flow from the remap fluxes): the running total and its time series, one sample per step, so
// that mass on the grid + discharged mass stays the initial mass to round-off and the
// discharge rate is the slope of the series.
#include <utility>
#include <vector>

#include "fullsim/cel/cel_grid.hpp"

namespace feedflow::cel {

struct DischargeSample {
  double time = 0.0;  // end of the step [s]
  double mass = 0.0;  // discharged up to then, per unit depth [kg/m]
};

class DischargeLedger {
 public:
  void book(double time, double mass, const NodeVector& momentum) {
    total_ += mass;
    momentum_ += momentum;
    history_.push_back({time, total_});
  }
  // Restores a ledger from its parts (checkpoint).
  DischargeLedger(double total, const NodeVector& momentum, std::vector<DischargeSample> history)
      : total_(total), momentum_(momentum), history_(std::move(history)) {}
  DischargeLedger() = default;

  double total() const { return total_; }                   // [kg/m]
  const NodeVector& momentum() const { return momentum_; }  // carried out [kg m/s /m]
  const std::vector<DischargeSample>& history() const { return history_; }

 private:
  double total_ = 0.0;
  NodeVector momentum_ = NodeVector::Zero();
  std::vector<DischargeSample> history_;
};

}  // namespace feedflow::cel
