#pragma once
// Verifying a drum's or a chute's answers on a full rung, for `design --verify`: one simulation of
// the case as `feedflow simulate --solver S` runs it (kept below the verification folder and read
// back on a second call), whose record holds each simulated quantity beside the reduced one
// (`<key>_reduced_model`). Each such quantity then stands in the design record in place of the
// reduced one, which stays beside it, and is verified when the two agree (numbers: the reduced
// band and the simulated one overlap, or for a time average the interval of its mean
// (`<key>_interval`: the drum's angle); labels: the same) or contradicted, with both answers;
// the verdict is judged again on the simulated ones. A chute's layer thinner than the run resolves
// (two particle diameters, two cells) is not taken: the reduced answer stands and a note says why.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "designer/bench/bench_run.hpp"
#include "designer/case/case.hpp"
#include "designer/simulate/simulation_request.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

struct SimulationVerification {
  Solver solver = Solver::dem;
  BenchRun run;
  std::filesystem::path folder;  // the run's folder (its snapshots)
  bool made = false;             // run now, not read back
};

SimulationVerification verify_by_simulation(const std::string& case_file,
                                            const std::vector<std::string>& sets, Solver solver,
                                            const std::filesystem::path& runs_folder,
                                            std::ostream* progress);

void apply_simulation_verification(const Case& c, const SimulationVerification& v,
                                   DesignRecord& record);

}  // namespace feedflow
