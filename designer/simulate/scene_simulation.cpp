#include "designer/simulate/scene_simulation.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <sstream>

#include "designer/design/target_units.hpp"
#include "designer/design/verdict_builder.hpp"
#include "designer/equipment/equipment_registry.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "designer/simulate/restart_identity.hpp"
#include "fullsim/common/progress_line.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

// A checkpoint that cannot be read into this scene is bad input (the --restart file), named.
template <class F>
void restoring(const SimulationRequest& request, F&& f) {
  try {
    f();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {  // a damaged file can also give absurd sizes (length, bad_alloc)
    throw InputError("--restart", "", request.restart.string() + " is damaged or not a checkpoint of this scene: " +
                                          e.what());
  }
}

// Ctrl-C stopped the fill: its checkpoint (with the case's identity) when the adapter can save
// one, else a note that nothing can be continued.
SimulationOutcome interrupted_while_filling(const SceneAdapter& adapter, const SimulationRequest& request,
                                            const std::vector<InputValue>& identity) {
  SimulationOutcome out;
  out.end = SimulationEnd::interrupted;
  VerdictBuilder v;
  const std::filesystem::path checkpoint = scene_checkpoint_path(request.out);
  const bool on_disk = request.ranks.rank() == 0;
  const bool saved = !request.out.empty() && write_whole_checkpoint(checkpoint, on_disk, [&](Hdf5File& f) {
    if (!adapter.save_fill(f)) return false;
    save_restart_identity(identity, f);
    return true;
  });
  if (saved) {
    if (on_disk) out.files.push_back(checkpoint);
    v.note("interrupted while filling " + adapter.what() + ": the fill continues from the checkpoint");
  } else {
    v.note("interrupted while filling " + adapter.what() + " before its first batch was in: no checkpoint, run again");
  }
  out.record.verdict = v.verdict();
  return out;
}

}  // namespace

SimulationOutcome simulate_scene(SceneAdapter& adapter, const SimulationRequest& request) {
  std::ostringstream discard;
  std::ostream& log = request.log ? *request.log : discard;
  TerminalProgress progress = TerminalProgress::for_terminal(!request.progress);
  const std::vector<InputValue> identity = restart_identity(request.case_data, request.solver);
  // A checkpoint of the fill is read before the build, which finishes the fill; one of the run
  // after it (the build makes the structure it is restored into).
  std::optional<Hdf5File> restart;
  if (!request.restart.empty())
    restoring(request, [&] {
      restart.emplace(request.restart, Hdf5File::Mode::read);
      check_restart_identity(identity, *restart);
      if (adapter.restore_fill(*restart)) {
        log << "continuing the fill from " << request.restart.string() << "\n";
        restart.reset();
      }
    });
  const auto build_start = std::chrono::steady_clock::now();
  Stepper* stepper = adapter.build(log, progress);
  if (!stepper) return interrupted_while_filling(adapter, request, identity);
  const double build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();

  SceneRunOptions run;
  run.setup_seconds = build_seconds;
  run.columns = adapter.columns();
  run.out = request.out;
  run.log = request.log;
  run.progress = &progress;
  run.checkpoint_every = request.checkpoint_every;
  if (restart) {
    run.restart = request.restart;
    restoring(request, [&] {
      run.previous = restore_scene_run(*stepper, *restart, run.columns);
      adapter.restore(*restart);
    });
    log << "restarted from " << request.restart.string() << " at t = " << stepper->time() << " s\n";
  }
  adapter.plan(run);
  run.save_scene = [&identity, save = std::move(run.save_scene)](Hdf5File& f) {
    save_restart_identity(identity, f);
    if (save) save(f);
  };
  const SceneRunResult result = run_scene(*stepper, run);

  SimulationOutcome out;
  out.series = result.series;
  out.files = result.files;
  out.end = result.end == RunEnd::interrupted ? SimulationEnd::interrupted : SimulationEnd::completed;
  DesignRecord& record = out.record;
  adapter.measure(result, record);
  PerformanceBlock performance{result.performance.title(), result.performance.wall_seconds(),
                               result.performance.figures(), result.performance.phases()};
  record.performance.push_back(std::move(performance));
  add_reduced_model_results(request.case_data, adapter.reduced_model_quantities(), record);
  // The judge of every rung, then the adapter's notes on the run.
  const std::vector<std::string> notes = std::move(record.verdict.reasons);
  VerdictBuilder verdict;
  show_in_target_units(request.case_data, record.results);
  for (auto& finding : equipment_of(request.case_data.kind()).judge(request.case_data, record.results).findings)
    verdict.add(std::move(finding));
  for (const auto& note : notes) verdict.add(Finding{.text = note});
  record.verdict = verdict.verdict();
  adapter.explain(result, record);
  return out;
}

}  // namespace feedflow
