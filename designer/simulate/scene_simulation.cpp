#include "designer/simulate/scene_simulation.hpp"

#include <sstream>

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

SimulationOutcome interrupted_while_filling(const std::string& what) {
  SimulationOutcome out;
  out.end = SimulationEnd::interrupted;
  VerdictBuilder v;
  v.note("interrupted while filling " + what + ": no checkpoint was written, run again");
  out.record.verdict = v.verdict();
  return out;
}

}  // namespace

SimulationOutcome simulate_scene(SceneAdapter& adapter, const SimulationRequest& request) {
  std::ostringstream discard;
  std::ostream& log = request.log ? *request.log : discard;
  TerminalProgress progress = TerminalProgress::for_terminal(!request.progress);
  Stepper* stepper = adapter.build(log, progress);
  if (!stepper) return interrupted_while_filling(adapter.what());

  SceneRunOptions run;
  run.columns = adapter.columns();
  run.out = request.out;
  run.restart = request.restart;
  run.log = request.log;
  run.progress = &progress;
  const std::vector<InputValue> identity = restart_identity(request.case_data, request.solver);
  if (!request.restart.empty())
    restoring(request, [&] {
      const Hdf5File f(request.restart, Hdf5File::Mode::read);
      check_restart_identity(identity, f);
      run.previous = restore_scene_run(*stepper, f, run.columns);
      adapter.restore(f);
    });
  if (!request.restart.empty())
    log << "restarted from " << request.restart.string() << " at t = " << stepper->time() << " s\n";
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
  add_reduced_model_results(request.case_data, adapter.reduced_model_quantities(), record);
  // The judge of every rung, then the adapter's notes on the run.
  const std::vector<std::string> notes = std::move(record.verdict.reasons);
  VerdictBuilder verdict;
  for (auto& finding : equipment_of(request.case_data.kind()).judge(request.case_data, record.results).findings)
    verdict.add(std::move(finding));
  for (const auto& note : notes) verdict.add(Finding{.text = note});
  record.verdict = verdict.verdict();
  adapter.explain(result, record);
  return out;
}

}  // namespace feedflow
