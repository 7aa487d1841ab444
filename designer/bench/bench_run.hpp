#pragma once
// One run of a bench point, in this process (no process per point): the design check with the
// point's model choices, or the simulation with its solver and settings, timed; and the run
// saved in its folder (run.json), so an interrupted or repeated bench skips what is done. A
// simulation cut short (Ctrl-C, SIGTERM) keeps its checkpoint there and continues from it when
// the point is run again. The drum's angle and regime questions ask for the same runs, which are
// made once.
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "designer/bench/bench_plan.hpp"

namespace feedflow {

struct BenchRun {
  std::string invocation;          // the command a user would type for it
  std::string status = "done";     // "done", "interrupted" (Ctrl-C) or "failed: <why>"
  double wall_seconds = 0.0;       // [s] of the check or the simulation (loading included)
  int cores = 1;                   // threads it ran on
  nlohmann::ordered_json results;  // the record's results, as results.json has them
  nlohmann::ordered_json verdict;  // the record's verdict, as results.json has it (null before it was kept)
  std::string commit;              // the program's commit that made it ("" for runs saved before it was kept)
  std::string inputs;              // bench_inputs_fingerprint when it was made ("" for runs saved before)
  bool done() const { return status == "done"; }
};

// The budget a verified point's command names: the bench measures what its runs take.
inline constexpr const char* kUnlimitedVerificationBudget = "10000h";

// The command line of the point: "simulate cases/pilot_hopper.toml --solver cel --set ...", or
// for a verified design check "design ... --verify dem --width-tolerance 2.5mm --budget 10000h".
std::string bench_invocation(const BenchQuestion& question, const BenchPoint& point);
// The folder of the point's run below `root` (shared by questions asking for the same run).
std::filesystem::path bench_run_folder(const std::filesystem::path& root, const BenchQuestion& question,
                                       const BenchPoint& point);

// What a point's answer depends on besides its command line, as a fingerprint: the text of the
// case file and of its material, without the material's [calibration] for a simulation (no
// solver reads it, so recalibrating does not make hours of runs stale). "" when the case does
// not load (the run then fails and says why).
std::string bench_inputs_fingerprint(const BenchQuestion& question, const BenchPoint& point,
                                     const std::filesystem::path& source_root);

// Runs the point (not a verified one: designer/verify/verified_bench_point.hpp runs those):
// case files relative to `source_root`; a simulation's files go to `folder`,
// continuing from the checkpoint `restart` when one is given. A run that fails (bad input, a
// blow-up) or is interrupted comes back with its status, never as a throw.
BenchRun run_bench_point(const BenchQuestion& question, const BenchPoint& point,
                         const std::filesystem::path& source_root,
                         const std::filesystem::path& folder,
                         const std::filesystem::path& restart = {});

// The run saved in `folder` for this invocation and these inputs; none when there is none, it
// was made for another invocation or other inputs, was interrupted, or is damaged. A run saved
// before inputs were fingerprinted counts when `accept_unfingerprinted` (a simulation: hours to
// redo) and it has results (a run whose case file could not be read has no fingerprint either).
std::optional<BenchRun> saved_bench_run(const std::filesystem::path& folder, const std::string& invocation,
                                        const std::string& inputs, bool accept_unfingerprinted);
// A run as run.json holds it, and back (throws on a damaged one).
nlohmann::ordered_json bench_run_json(const BenchRun& run);
BenchRun bench_run_from_json(const nlohmann::ordered_json& json);
// Writes folder/run.json whole (a temporary renamed over it).
void save_bench_run(const std::filesystem::path& folder, const BenchRun& run);

// The point's run saved in `folder` when it counts for these inputs (saved_bench_run).
std::optional<BenchRun> saved_run_of(const BenchQuestion& question, const BenchPoint& point,
                                     const std::filesystem::path& source_root, const std::filesystem::path& folder);

// The simulation of this invocation and these inputs that was cut short in `folder`, with its
// wall time so far, when its checkpoint (interrupted_checkpoint) is there to continue from.
std::optional<BenchRun> interrupted_bench_run(const std::filesystem::path& folder,
                                              const std::string& invocation,
                                              const std::string& inputs);
// A simulation of this invocation and inputs killed outright (no Ctrl-C: its run.json still
// marks it cut short, and the checkpoint it wrote on the way is the scene's): that checkpoint
// becomes the one the next call continues from.
void adopt_checkpoint_of_killed_run(const std::filesystem::path& folder,
                                    const std::string& invocation, const std::string& inputs);
// Where a run cut short keeps its checkpoint in its folder.
std::filesystem::path interrupted_checkpoint(const std::filesystem::path& folder);
// What a command cut short tells its user: its runs are kept in `runs` and the same command
// continues them.
std::string continue_after_interrupt(const std::filesystem::path& runs);

// The point's run read back from `folder`, or made and saved; `made` says which. A simulation
// cut short is saved as interrupted with its checkpoint, and the next call continues it from
// there: its wall time adds up, and its commit names both builds when they differ.
BenchRun run_or_read_back(const BenchQuestion& question, const BenchPoint& point,
                          const std::filesystem::path& source_root, const std::filesystem::path& folder, bool& made);

}  // namespace feedflow
