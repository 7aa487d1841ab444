#include "designer/verify/rejudge.hpp"

#include <set>
#include <string>

#include "designer/design/judge.hpp"
#include "designer/design/verdict_builder.hpp"

namespace feedflow {

void rejudge(const Case& c, DesignRecord& record) {
  std::set<std::string> from_findings;  // the reasons the findings gave (VerdictBuilder::add)
  for (const auto& f : record.verdict.findings)
    from_findings.insert(f.status ? std::string(to_string(*f.status)) + ": " + f.text : f.text);
  VerdictBuilder rejudged;
  std::set<std::string> made;
  for (auto& f : judge(c, record.results).findings) {
    made.insert(f.text);
    rejudged.add(std::move(f));
  }
  for (const auto& f : record.verdict.findings)
    if (!f.status && !made.count(f.text)) rejudged.add(f);
  Verdict verdict = rejudged.verdict();
  for (const auto& r : record.verdict.reasons)
    if (!from_findings.count(r)) verdict.reasons.push_back(r);
  record.verdict = std::move(verdict);
}

}  // namespace feedflow
