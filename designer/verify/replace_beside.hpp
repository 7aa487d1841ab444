#pragma once
// A full rung's answer put in a record in place of the reduced one, which is kept beside it
// under reduced_model_key (the report shows both).
#include <string>

#include "models/core/design_record.hpp"

namespace feedflow {

// Puts `rung` in place of the record's `key` (it takes the reduced one's display unit) and
// keeps the reduced estimate right after it; appends `rung` when there is none.
void replace_beside(Estimates& results, const std::string& key, Estimate rung);

// The particle rung's bracket on a length (a threshold bisection's largest size that stopped and
// smallest that flowed, [m]) as an estimate on L3: its middle, the two as its band, shown in mm.
Estimate particle_bracket(double stops_at, double flows_at, std::string model);

}  // namespace feedflow
