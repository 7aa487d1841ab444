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

VerdictStatus at_least(double value, double low, double required) {
  if (low >= required) return VerdictStatus::pass;
  if (value >= required) return VerdictStatus::marginal;
  return VerdictStatus::fail;
}

VerdictStatus at_most(double value, double high, double allowed) {
  if (high <= allowed) return VerdictStatus::pass;
  if (value <= allowed) return VerdictStatus::marginal;
  return VerdictStatus::fail;
}

void VerdictBuilder::add(VerdictStatus status, std::string reason) {
  if (!judged_ || severity(status) > severity(verdict_.status)) verdict_.status = status;
  judged_ = judged_ || status != VerdictStatus::unknown;
  verdict_.reasons.push_back(std::string(to_string(status)) + ": " + reason);
}

void VerdictBuilder::add(Finding finding) {
  if (finding.status)
    add(*finding.status, finding.text);
  else
    note(finding.text);
  verdict_.findings.push_back(std::move(finding));
}

VerdictStatus VerdictBuilder::judge_at_least(double value, double low, double required) {
  return at_least(value, low, required);
}

}  // namespace feedflow
