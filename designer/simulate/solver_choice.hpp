#pragma once
// Which full simulation verifies a case. Asked for by name (--solver dem|cel) or chosen by the
// rule of the seed paper (section 4): the continuum for pilot and industrial scale, particles
// for small systems.
#include <optional>
#include <string>

#include "designer/case/case.hpp"
#include "designer/simulate/simulation_request.hpp"

namespace feedflow {

struct SolverChoice {
  Solver solver = Solver::dem;
  std::string reason;  // one line for the log and the record's assumptions
};

// "dem" or "cel" (throws InputError naming --solver for anything else).
Solver parse_solver(const std::string& text);
// `asked` if given, otherwise the seed's rule applied to the case.
SolverChoice choose_solver(const Case& c, std::optional<Solver> asked);

}  // namespace feedflow
