#pragma once
// The run loop every full-simulation scene shares (DEM and CEL; hopper, chute, drum): runs a
// Stepper from where it stands until `duration` after the scene's origin (the gate opened, the
// shell started: given, or the stepper's event_started_at() once its scene event has happened),
// unless the stop predicate ends it first (the measured quantity has converged, the flow has
// stopped). On the way: a sampled time series, field snapshots, progress with an ETA, the
// interrupt flag (Ctrl-C), and at the end or on an interrupt (and every `checkpoint_every` of
// wall time) a checkpoint whose /scene group holds the series and the scene's own data, so a
// restarted run continues the same series.
// The plan line, the end and the performance block go to the log sink; nothing is printed.
//
// Sample and snapshot times and the end are planned on the stepper's step grid
// (Stepper::whole_steps), counted from a fixed origin (`sample_origin`, for samples and
// snapshots), so a restarted run samples, writes and stops at the same steps as an
// uninterrupted one. A snapshot interval of whole sample intervals falls on the rows' steps.
//
//   SceneRunOptions o;  o.out = folder;  o.duration = 5.0;  o.columns = {...};
//   o.sample = [&] { return std::vector<double>{engine.time(), ...}; };
//   o.stop = [&](const TimeSeries& s) { return converged(s) ? "converged: ..." : ""; };
//   SceneRunResult r = run_scene(engine, o);
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/common/progress_sink.hpp"
#include "fullsim/common/stepper.hpp"
#include "models/core/time_series.hpp"

namespace feedflow {

struct SceneRunOptions {
  std::string label = "run";            // progress label ("DEM hopper")
  std::filesystem::path out;            // output folder: checkpoint.h5 and the snapshots
  // The checkpoint this run continues from (its stepper and scene already restored from it:
  // restore_scene_run()); empty: a new run.
  std::filesystem::path restart;
  // [s] The measured phase's start; unset: the stepper's event_started_at() (known once its scene
  // event has happened; until then the loop plans with `latest_origin` for the progress line).
  std::optional<double> origin;
  double latest_origin = 0.0;           // [s]
  double duration = 1.0;                // [s] after the origin
  // Rows at sample_origin + k sample_interval, from k = 0 (`sample_at_origin`) or k = 1.
  double sample_origin = 0.0;           // [s]
  bool sample_at_origin = true;
  double sample_interval = 0.01;        // [s] between rows
  double snapshot_interval = 0.0;       // [s] between snapshots, from sample_origin; <= 0: none
  std::vector<TimeSeriesColumn> columns;
  std::function<std::vector<double>()> sample;  // one row, taken at the sample times
  // Asked after every row: a non-empty reason ends the run there ("converged: ...").
  std::function<std::string(const TimeSeries&)> stop;
  // Writes the scene's own data into the checkpoint's /scene group (which exists).
  std::function<void(Hdf5File&)> save_scene;
  TimeSeries previous;                  // the rows of the run this one continues
  // [s] Wall time spent before this loop on the same stepper (a DEM scene's fill, whose steps
  // are in the engine's phases): the block's wall time covers it, and it is shown on its own.
  double setup_seconds = 0.0;
  std::string setup_name = "fill";
  // [s] of wall time between checkpoints written on the way (the end's file, whole or not at
  // all), so that a run killed outright (power, the OOM killer, a scheduler's hard limit)
  // continues from the last one; <= 0: a checkpoint only at the end or on Ctrl-C.
  double checkpoint_every = 0.0;
  long steps_between_checks = 200;      // steps between interrupt checks and progress updates
  std::ostream* log = nullptr;          // plan line, end, performance block; null: silent
  ProgressSink* progress = nullptr;     // null: none
};

enum class RunEnd { duration, stopped, interrupted };

struct SceneRunResult {
  TimeSeries series;
  RunEnd end = RunEnd::duration;
  std::string stop_reason;              // RunEnd::stopped: why
  std::vector<std::filesystem::path> files;  // snapshots, sidecar, checkpoint
  double wall_seconds = 0.0;
  RunReport performance{"run"};         // the engine's block with the loop's phases
};

SceneRunResult run_scene(Stepper& stepper, const SceneRunOptions& options);

// Writes a checkpoint whole or not at all: `write` fills a temporary beside `path`, which is
// then renamed over it, or returns false (nothing to save: no file, returns false). Throws
// std::runtime_error naming `path`. Not `on_disk`: `write` fills a file in memory, which is
// dropped (a process of a shared run that does not write files).
bool write_whole_checkpoint(const std::filesystem::path& path, bool on_disk,
                            const std::function<bool(Hdf5File&)>& write);

// The checkpoint file of a scene run in `folder`.
std::filesystem::path scene_checkpoint_path(const std::filesystem::path& folder);

// Restoring a run: the stepper's state from `checkpoint`, and the series saved beside it (which
// must have `columns`); the scene's own data is read from the returned file's /scene group.
// Throws std::runtime_error naming the file and what does not fit.
TimeSeries restore_scene_run(Stepper& stepper, const Hdf5File& checkpoint,
                             const std::vector<TimeSeriesColumn>& columns);

}  // namespace feedflow
