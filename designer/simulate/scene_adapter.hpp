#pragma once
// What turns a case into a full-simulation scene on one rung and its run back into design
// quantities: one adapter per equipment and solver (dem_hopper_adapter, cel_drum_adapter, ...).
// The shared flow (scene_simulation.hpp) calls, in order: build, restore (a restart: the
// engine's state and the series first), plan, the scene run loop (fullsim/common/scene_run.hpp),
// measure, then the equipment's judge, and explain. An adapter holds the scene it built; it is
// made for one request.
#include <ostream>
#include <string>
#include <vector>

#include "designer/simulate/simulation_request.hpp"
#include "fullsim/common/scene_run.hpp"

namespace feedflow {

class SceneAdapter {
 public:
  virtual ~SceneAdapter() = default;

  // "the hopper", "the drum": what a fill interrupted by Ctrl-C was filling.
  virtual std::string what() const = 0;
  // A restart from a checkpoint of a fill stopped by Ctrl-C (save_fill): reads the fill's
  // state (before build, which then finishes the fill) and returns true; false when the file
  // holds no fill under way (a checkpoint of the run, restored after build).
  virtual bool restore_fill(const Hdf5File&) { return false; }
  // Builds the scene. A new run: up to its origin (a DEM fill rained in, or the rest of a
  // restored one, settled and trimmed, the gate opened). A restart of the run: its structure
  // only (walls, meshes, grid), which the caller restores from the checkpoint. Returns null
  // when Ctrl-C stopped the fill. Writes the scene's plan to `log`, the fill's progress to
  // `progress`.
  virtual Stepper* build(std::ostream& log, ProgressSink& progress) = 0;
  // After build returned null: the checkpoint of the fill under way into `file` (false:
  // nothing to continue from, the fill had not begun).
  virtual bool save_fill(Hdf5File&) const { return false; }
  // The columns of the scene's time series.
  virtual std::vector<TimeSeriesColumn> columns() const = 0;
  // A restart: the scene's own data from the checkpoint's /scene group (saved by the
  // options' save_scene of the run that wrote it).
  virtual void restore(const Hdf5File&) {}
  // The run: label, origin, duration, sampling, snapshots, the stop predicate and save_scene.
  // The caller has filled the columns, the output folder, the restart and its series
  // (`run.previous`), the log and the progress.
  virtual void plan(SceneRunOptions& run) = 0;
  // The quantities measured on the run (rung L2 or L3) into `record.results`, and notes about
  // the run (not converged, interrupted) into `record.verdict.reasons`.
  virtual void measure(const SceneRunResult& run, DesignRecord& record) = 0;
  // The reduced-model quantities shown beside the measured ones ("<name>_reduced_model").
  virtual std::vector<std::string> reduced_model_quantities() const = 0;
  // Charts and assumptions (what the scene assumes and which way each number errs); the
  // reduced-model values are in `record` by now.
  virtual void explain(const SceneRunResult& run, DesignRecord& record) = 0;
};

}  // namespace feedflow
