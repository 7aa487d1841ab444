#pragma once
// The hopper design check: flow pattern, flow factor, critical outlet width, discharge rate,
// each with its band, judged against the case's [design] targets.
#include "designer/case/case.hpp"
#include "designer/design/model_choices.hpp"
#include "designer/design/verdict_builder.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

void check_hopper(const Case& c, const Hopper& hopper, const ModelChoices& models,
                  DesignRecord& record, VerdictBuilder& verdict);

}  // namespace feedflow
