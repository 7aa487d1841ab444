#pragma once
// What `feedflow simulate` asks of a full simulation, and what one gives back. simulate()
// (simulation.hpp) picks the equipment's scene adapter for the rung, which builds the scene from
// the case, runs it and measures the design quantities; the command writes the files.
#include <filesystem>
#include <optional>
#include <ostream>
#include <vector>

#include "designer/case/case.hpp"
#include "fullsim/dem/ranks/dem_ranks.hpp"
#include "models/core/design_record.hpp"
#include "models/core/time_series.hpp"

namespace feedflow {

enum class Solver { dem, cel };
const char* to_string(Solver solver);

// A run killed outright loses at most this much wall time: 30 min.
inline constexpr double kCheckpointEvery = 1800.0;

struct SimulationRequest {
  Case case_data;
  Solver solver = Solver::dem;
  std::optional<double> end_time;   // --time [s]; none: the scene's own end (converged, stopped)
  std::filesystem::path out;        // output folder (exists when the solver is called)
  std::filesystem::path restart;    // checkpoint to continue from; empty: a new run
  bool progress = true;             // progress line with ETA on a terminal
  std::ostream* log = nullptr;      // plan, phases and performance block; null: silent
  // The processes a DEM run is shared among (each runs the same scene; the first writes the
  // files); one: alone. The CEL solver runs alone.
  DemRanks ranks = DemRanks::one();
  // [s] of wall time between the checkpoints a run writes on the way (after a DEM scene's fill);
  // <= 0: at the end or on Ctrl-C only.
  double checkpoint_every = kCheckpointEvery;
};

enum class SimulationEnd { completed, interrupted };

struct SimulationOutcome {
  // Results (rung "L3" for DEM, "L2" for CEL-FEM), verdict, charts and assumptions; inputs
  // and provenance are filled in by the command.
  DesignRecord record;
  TimeSeries series;                              // written as timeseries.csv
  std::vector<std::filesystem::path> files;       // snapshots, sidecars, checkpoints written
  SimulationEnd end = SimulationEnd::completed;   // interrupted: a checkpoint was written
};

}  // namespace feedflow
