#pragma once
// The resolved inputs of a case as the record lists them: every field in SI with its unit, and
// how a person reads it.
#include <string>
#include <vector>

#include "designer/case/case.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

std::vector<InputValue> case_inputs(const Case& c);
// The [dem] and [cel] settings that the case gives ("dem.slab_depth", "cel.cell_size", ...).
std::vector<InputValue> simulation_inputs(const Case& c);

// Fills what a record says of its case: version, name, kind, file, description and inputs.
void describe_case(const Case& c, DesignRecord& record);

// One parameter of a material, as `feedflow materials NAME` lists it.
struct MaterialParameter {
  InputValue value;         // key without the "material." prefix: "bulk.density"; with its source
  std::string description;  // what the parameter means
};
std::vector<MaterialParameter> material_parameters(const Material& m);

}  // namespace feedflow
