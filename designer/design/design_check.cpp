#include "designer/design/design_check.hpp"

#include "designer/design/case_inputs.hpp"
#include "models/core/version.hpp"

namespace feedflow {

DesignRecord design_check(const Case& c) {
  DesignRecord record;
  record.feedflow_version = kVersion;
  record.case_name = c.name;
  record.kind = c.kind();
  record.case_file = c.file;
  record.description = c.description;
  record.inputs = case_inputs(c);
  // No reduced model is wired in yet: nothing is computed, and the verdict says so rather than
  // showing placeholder numbers.
  record.verdict.status = VerdictStatus::unknown;
  record.verdict.reasons.push_back(std::string("no reduced model for a ") + to_string(c.kind()) +
                                   " is available in this build yet, so nothing was computed");
  return record;
}

}  // namespace feedflow
