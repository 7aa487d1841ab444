#pragma once
// The designer's answer to a case: the reduced models that apply, their estimates and the
// verdict against the case's targets.
#include "designer/case/case.hpp"
#include "designer/design/design_detail.hpp"
#include "designer/design/model_choices.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

// Runs the design check of a case. `wall_seconds` is left for the caller to fill in. With
// DesignDetail::results the record holds the results and the verdict only (no inputs, charts or
// assumptions).
DesignRecord design_check(const Case& c, const ModelChoices& models = {},
                          DesignDetail detail = DesignDetail::full);

}  // namespace feedflow
