#pragma once
// The run phase of every DEM scene of `feedflow simulate` (hopper, chute, drum), scene-
// independent: runs a prepared DemEngine from the scene's origin (e.g. the gate opening) for a
// duration or until the scene's stop predicate says the measured quantity has converged or the
// flow has stopped; a ProgressLine with ETA (request.progress), HDF5 particle snapshots with
// their XDMF sidecar at the snapshot interval, a TimeSeries sampled every `sample_interval`,
// a checkpoint at the end and on Ctrl-C (with the series and the scene's own data in a
// /scene group, so a restart continues the series), the performance block to request.log.
// Sampling, snapshots and the end are counted in steps from the origin, so a restarted run
// samples and stops at the same steps as an uninterrupted one (bit-identical state).
//
//   DemSceneRun run;  run.origin_step = ...; run.duration = 5.0; run.columns = {...};
//   run.sample = [](const DemEngine& e) { return std::vector<double>{e.time(), ...}; };
//   run.stop = [](const DemEngine& e, const TimeSeries& s) { return std::string(); };
//   DemSceneResult r = run_dem_scene(engine, request, run);
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "designer/simulate/simulation_request.hpp"
#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/dem/dem_engine.hpp"

namespace feedflow {

struct DemSceneRun {
  std::string label = "DEM";           // progress label
  long origin_step = 0;                // the step the run phase starts from (not a restart's)
  double duration = 1.0;               // [s] after the origin
  double sample_interval = 0.01;       // [s] between time-series rows
  double snapshot_interval = 0.0;      // [s] between particle snapshots; <= 0: none
  std::vector<TimeSeriesColumn> columns;
  std::function<std::vector<double>(const DemEngine&)> sample;
  // Called after each sample: a non-empty reason ends the run early ("converged: ...").
  std::function<std::string(const DemEngine&, const TimeSeries&)> stop;
  // Writes the scene's own data (e.g. the fill report) into the checkpoint's /scene group.
  std::function<void(Hdf5File&)> save_scene;
  TimeSeries previous;                 // rows restored from a checkpoint (restart)
};

struct DemSceneResult {
  TimeSeries series;
  SimulationEnd end = SimulationEnd::completed;
  std::string stop_reason;             // empty: the duration ran out
  std::vector<std::filesystem::path> files;  // snapshots, sidecar, checkpoint
  double wall_seconds = 0.0;
};

DemSceneResult run_dem_scene(DemEngine& engine, const SimulationRequest& request,
                             const DemSceneRun& run);

// The time series saved in a checkpoint's /scene group (empty rows when there is none).
TimeSeries read_scene_series(const Hdf5File& checkpoint, std::vector<TimeSeriesColumn> columns);

// The outcome of a run stopped by Ctrl-C while filling `what` ("the drum"): no checkpoint (a
// restart would skip the fill), a verdict that says so.
SimulationOutcome interrupted_while_filling(const std::string& what);

// Steps of `dt` in `seconds` (at least one).
long steps_in(double seconds, double dt);

}  // namespace feedflow
