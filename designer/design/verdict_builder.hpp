#pragma once
// Collects the findings of a design check into a verdict: the worst status wins, every finding
// keeps its reason in words. A check with nothing to judge stays "unknown".
#include <string>

#include "models/core/design_record.hpp"

namespace feedflow {

// The two rules a number is judged by. The requirement is exact and the estimate has a band:
// clear of the band is a pass, inside it (the value meets the requirement, its band does not)
// marginal, the value itself short of it a fail.
// Larger is better (a throughput): pass when low >= required, marginal when value >= required.
VerdictStatus at_least(double value, double low, double required);
// Smaller is better (a deposit, a critical width): pass when high <= allowed, marginal when
// value <= allowed.
VerdictStatus at_most(double value, double high, double allowed);

class VerdictBuilder {
 public:
  void pass(std::string reason) { add(VerdictStatus::pass, std::move(reason)); }
  void marginal(std::string reason) { add(VerdictStatus::marginal, std::move(reason)); }
  void fail(std::string reason) { add(VerdictStatus::fail, std::move(reason)); }
  // A reason that does not judge (e.g. a model that could not be applied).
  void note(std::string reason) { verdict_.reasons.push_back(std::move(reason)); }
  void add(VerdictStatus status, std::string reason);
  // A reason with its quantity and numbers: judges when it has a status, notes otherwise. Its
  // text becomes a reason as above, and the finding is kept in the verdict.
  void add(Finding finding);

  // at_least(value, low, required), for callers that add the reason themselves.
  VerdictStatus judge_at_least(double value, double low, double required);

  const Verdict& verdict() const { return verdict_; }
  bool judged() const { return judged_; }

 private:
  Verdict verdict_;
  bool judged_ = false;
};

}  // namespace feedflow
