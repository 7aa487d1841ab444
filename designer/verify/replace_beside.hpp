#pragma once
// A full rung's answer put in a record in place of the reduced one, which is kept beside it
// under reduced_model_key (the report shows both).
#include <string>

#include "models/core/design_record.hpp"

namespace feedflow {

// Puts `rung` in place of the record's `key` (it takes the reduced one's display unit) and
// keeps the reduced estimate right after it; appends `rung` when there is none.
void replace_beside(Estimates& results, const std::string& key, Estimate rung);

}  // namespace feedflow
