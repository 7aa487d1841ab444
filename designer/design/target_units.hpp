#pragma once
// Results shown in the unit of the design target they are judged against, as the engineer wrote
// it: a throughput required in t/h puts every mass flow rate of the record in t/h (the value
// stays SI inside; only Estimate::display_unit changes).
#include "designer/case/case.hpp"

namespace feedflow {

void show_in_target_units(const Case& c, Estimates& results);

}  // namespace feedflow
