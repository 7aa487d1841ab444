#pragma once
// The chute design check: stopping thickness on the ramp (Pouliquen's law, L0) and the deposit
// of a release from the bin (depth-averaged flow, L1), against the case's targets.
#include "designer/case/case.hpp"
#include "designer/design/model_choices.hpp"
#include "designer/design/verdict_builder.hpp"

namespace feedflow {

void check_chute(const Case& c, const Chute& chute, const ModelChoices& models, DesignRecord& record,
                 VerdictBuilder& verdict);

}  // namespace feedflow
