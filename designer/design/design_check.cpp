#include "designer/design/design_check.hpp"

#include "designer/design/case_inputs.hpp"
#include "designer/design/verdict_builder.hpp"
#include "designer/equipment/equipment_registry.hpp"

namespace feedflow {

DesignRecord design_check(const Case& c, const ModelChoices& models) {
  DesignRecord record;
  describe_case(c, record);
  VerdictBuilder verdict;
  equipment_of(c.kind()).check(c, models, record, verdict);
  record.verdict = verdict.verdict();
  if (!verdict.judged()) record.verdict.status = VerdictStatus::unknown;
  return record;
}

}  // namespace feedflow
