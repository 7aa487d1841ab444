#pragma once
// What a checkpoint was written for: every input that changes the simulated physics (the
// equipment, the material's bulk values and the parameters of the rung's law, the rung's
// [dem] or [cel] settings), saved in the checkpoint's /scene/case group and compared on a
// restart, so that a checkpoint never continues another case. Left out: the design targets,
// the end time and snapshot interval (a restart may run longer or write more often), and the
// material tables only the reduced models read.
#include <vector>

#include "designer/case/case.hpp"
#include "designer/simulate/simulation_request.hpp"
#include "fullsim/common/hdf5_file.hpp"

namespace feedflow {

std::vector<InputValue> restart_identity(const Case& c, Solver solver);
void save_restart_identity(const std::vector<InputValue>& identity, Hdf5File& checkpoint);
// Throws InputError("--restart", key, "the checkpoint was written with X; this run gives Y")
// for the first input that differs, is missing from the checkpoint or was not there before.
void check_restart_identity(const std::vector<InputValue>& identity, const Hdf5File& checkpoint);

}  // namespace feedflow
