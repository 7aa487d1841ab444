#include "designer/design/verdict_builder.hpp"

namespace feedflow {
namespace {
int severity(VerdictStatus s) {
  switch (s) {
    case VerdictStatus::pass: return 1;
    case VerdictStatus::marginal: return 2;
    case VerdictStatus::fail: return 3;
    case VerdictStatus::unknown: return 0;
  }
  return 0;
}
}  // namespace

void VerdictBuilder::add(VerdictStatus status, std::string reason) {
  if (!judged_ || severity(status) > severity(verdict_.status)) verdict_.status = status;
  judged_ = judged_ || status != VerdictStatus::unknown;
  verdict_.reasons.push_back(std::string(to_string(status)) + ": " + reason);
}

VerdictStatus VerdictBuilder::judge_at_least(double value, double low, double required) {
  if (low >= required) return VerdictStatus::pass;
  if (value >= required) return VerdictStatus::marginal;
  return VerdictStatus::fail;
}

}  // namespace feedflow
