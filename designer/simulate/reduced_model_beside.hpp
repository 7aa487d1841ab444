#pragma once
// The reduced-model value of a quantity beside the simulated one: runs the design check of the
// same case and copies the named results under reduced_model_key(name), i.e.
// "<name>_reduced_model" (their own rung and band). Every simulated scene (DEM and CEL) uses it.
#include <string>
#include <vector>

#include "designer/case/case.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

// Returns the design check's verdict status for the notes; missing names are skipped.
void add_reduced_model_results(const Case& c, const std::vector<std::string>& names,
                               DesignRecord& record);

}  // namespace feedflow
