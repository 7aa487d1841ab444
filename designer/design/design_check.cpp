#include "designer/design/design_check.hpp"

#include "designer/design/case_inputs.hpp"
#include "designer/equipment/equipment_registry.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

DesignRecord design_check(const Case& c, const ModelChoices& models, DesignDetail detail) {
  DesignRecord record;
  if (detail == DesignDetail::results) {
    equipment_of(c.kind()).check(c, models, detail, record);
    return record;
  }
  describe_case(c, record);
  equipment_of(c.kind()).check(c, models, detail, record);
  if (c.material.bulk.moisture_content)
    record.assumptions.push_back("Moisture content " + format_quantity(*c.material.bulk.moisture_content, "%", 3) +
                                 " is informational: no model of this check reads it (its effect on the flow is "
                                 "in the measured flow properties, which must be taken at this moisture).");
  return record;
}

}  // namespace feedflow
