#pragma once
// The verdict on a full rung's estimates (L2, L3) against the case's [design] targets, one
// judge per equipment; it judges the quantities the run measured and nothing else.
#include "designer/case/case.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

Verdict judge_simulated_hopper(const Case& c, const DesignRecord& record);
Verdict judge_simulated_chute(const Case& c, const DesignRecord& record);
Verdict judge_simulated_drum(const Case& c, const DesignRecord& record);

}  // namespace feedflow
