#pragma once
// Collects the findings of a design check into a verdict: the worst status wins, every finding
// keeps its reason in words. A check with nothing to judge stays "unknown".
#include <string>

#include "models/core/design_record.hpp"

namespace feedflow {

class VerdictBuilder {
 public:
  void pass(std::string reason) { add(VerdictStatus::pass, std::move(reason)); }
  void marginal(std::string reason) { add(VerdictStatus::marginal, std::move(reason)); }
  void fail(std::string reason) { add(VerdictStatus::fail, std::move(reason)); }
  // A reason that does not judge (e.g. a model that could not be applied).
  void note(std::string reason) { verdict_.reasons.push_back(std::move(reason)); }
  void add(VerdictStatus status, std::string reason);

  // Judges `value` (larger is better) against `required`, with the band's low end: pass when
  // low >= required, marginal when value >= required, fail otherwise.
  VerdictStatus judge_at_least(double value, double low, double required);

  const Verdict& verdict() const { return verdict_; }
  bool judged() const { return judged_; }

 private:
  Verdict verdict_;
  bool judged_ = false;
};

}  // namespace feedflow
