#pragma once
// The deposit models of a chute (`--model chute.deposit=NAME`): the release from the bin run
// to rest on rung L1, or nothing (the stopping thickness of rung L0 stands alone).
#include <optional>

#include "models/chute/ramp_flow_solver.hpp"
#include "models/core/model_table.hpp"
#include "models/equipment/chute.hpp"

namespace feedflow {

struct ChuteDeposit {
  RampFlowResult run;  // at rest
  double cell_size;    // [m]
};

// Nothing for a row that runs no release. Throws NumericalFailure when the release does not
// come to rest.
using ChuteDepositEvaluate = std::optional<ChuteDeposit> (*)(const Chute& chute, const PouliquenLaw& law);
using ChuteDepositModel = ModelRow<ChuteDepositEvaluate>;

// l1 (default), none.
const ModelTable<ChuteDepositModel>& chute_deposit_models();

}  // namespace feedflow
