#pragma once
// The contract of a full-simulation engine, as the scene run loop (scene_run.hpp) sees it; the
// DEM engine (dem/dem_engine.hpp) and the CEL scene run (cel/cel_scene_run.hpp) implement it.
// After MFEM's ODESolver: the caller asks for a time, the engine takes its own steps.
//
//   engine.prepare(log);                       // time step, first forces, the plan
//   engine.advance_to(t + engine.whole_steps(0.01, StepRounding::nearest));
//   engine.write_checkpoint(file);             // ... and later, in a new process:
//   engine.restore(file);  engine.prepare(log);  // continues bit-identically
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/common/run_report.hpp"
#include "fullsim/common/snapshot_writer.hpp"

namespace feedflow {

// How whole_steps() puts a duration on the step grid of a fixed-step engine.
enum class StepRounding {
  nearest,  // the nearest whole number of steps, at least one (sample and snapshot intervals)
  up,       // the first whole number of steps that covers the duration (the end of a run)
};

class Stepper {
 public:
  static constexpr long kUnbounded = std::numeric_limits<long>::max();

  virtual ~Stepper() = default;

  // Makes the engine ready to step: chooses the time step, builds what the first step needs
  // (neighbour lists, first forces) and writes the plan to `log`. Engines write only to the
  // sinks they are given, never to a terminal. A second call does nothing; a restored engine
  // checks here that its settings fit the checkpoint (and throws naming what differs).
  virtual void prepare(std::ostream& log) = 0;

  // Advances by whole steps of the engine's own time step; a step is never shortened or
  // interpolated.
  // On entry: prepared (advance_to prepares a fresh engine silently otherwise).
  // On exit, the first of:
  //  - reached(t): a fixed-step engine stands on the first step at or past t, where a step
  //    less than a quarter step short of t counts as reaching it (so a time planned on the
  //    step grid with whole_steps() is met exactly, whatever the round-off of the summed
  //    time); an adaptive engine on the first step past t (time() >= t);
  //  - `max_steps` steps taken (so the caller can look at the interrupt flag and the clock);
  //  - a scene event happened in the last step (event_started_at() was unset on entry and is set).
  // Returns the steps taken (0 when reached(t) on entry).
  virtual long advance_to(double t, long max_steps = kUnbounded) = 0;
  // Whether advance_to(t) would take no step now.
  virtual bool reached(double t) const = 0;
  // `duration` on the engine's step grid (a fixed-step engine: a whole number of its steps,
  // rounded as asked; an adaptive engine: unchanged) [s].
  virtual double whole_steps(double duration, StepRounding rounding) const = 0;

  virtual double time() const = 0;  // [s]
  virtual long steps() const = 0;   // taken since the run began (a restored run's included)
  // When the scene's event happened (a CEL scene's gravity phase ends with the outlet opened,
  // the gate lifted, the shell started); unset before it and for engines without one.
  virtual std::optional<double> event_started_at() const { return std::nullopt; }

  // Writes the whole state into `file` (an open, new HDF5 file; its root and groups other than
  // /scene belong to the engine), and reads it back into an engine built from the same scene
  // (walls and meshes added, no state yet). Throws std::runtime_error naming what does not fit.
  virtual void write_checkpoint(Hdf5File& file) const = 0;
  virtual void restore(const Hdf5File& file) = 0;
  // Whether write_checkpoint() can be called now (a DEM engine right after particles were
  // inserted or removed needs a step first, which rebuilds its neighbour list).
  virtual bool checkpoint_ready() const { return true; }

  // An engine whose run is shared among processes (MPI ranks) runs the same scene loop on each:
  // the loop's decisions are agreed (a flag is raised if any process raised it; a failure on one
  // is a failure on all), and one process writes the files (the others build the same
  // checkpoint, in memory, and drop it). Alone: as given, and it writes.
  virtual bool raised_on_any(bool flag) const { return flag; }
  virtual std::optional<std::string> agreed_failure(std::optional<std::string> mine) const {
    return mine;
  }
  virtual bool writes_files() const { return true; }

  // The engine's field snapshots (HDF5 with an XDMF sidecar that ParaView opens) in `folder`;
  // `continuing`: a restarted run, whose first part's snapshots are kept.
  virtual std::unique_ptr<SnapshotWriter> snapshot_writer(const std::filesystem::path& folder,
                                                          bool continuing) const = 0;
  // The engine's part of the performance block: time per phase and throughput figures.
  virtual RunReport performance() const = 0;
};

}  // namespace feedflow
