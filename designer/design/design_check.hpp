#pragma once
// The designer's answer to a case: the reduced models that apply, their estimates and the
// verdict against the case's targets.
#include "designer/case/case.hpp"
#include "designer/design/model_choices.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

// Runs the design check of a case. `wall_seconds` is left for the caller to fill in.
DesignRecord design_check(const Case& c, const ModelChoices& models = {});

}  // namespace feedflow
