#include "designer/design/design_check.hpp"

#include "designer/design/case_inputs.hpp"
#include "designer/equipment/equipment_registry.hpp"

namespace feedflow {

DesignRecord design_check(const Case& c, const ModelChoices& models) {
  DesignRecord record;
  describe_case(c, record);
  equipment_of(c.kind()).check(c, models, record);
  return record;
}

}  // namespace feedflow
