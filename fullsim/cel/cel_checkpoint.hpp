#pragma once
// A checkpoint of a CEL scene run (HDF5, format "feedflow CEL checkpoint", units on every
// dataset): the solver state (cell and node fields, counters, wall event times, discharge
// ledger) and the scene run state (phase, event time, peak kinetic energy); the caller's time
// series beside it in /scene/series (the scene run loop's group, fullsim/common/scene_run.hpp).
// Reading it into a run built from the same scene continues bit-identically; a foreign,
// other-version or other-grid file is refused naming it.
#include <filesystem>
#include <vector>

#include "fullsim/cel/cel_scene_run.hpp"
#include "fullsim/common/hdf5_file.hpp"

namespace feedflow::cel {

inline constexpr const char* kCelCheckpointFormat = "feedflow CEL checkpoint";
// 2: the turning frame's start; 3: the samples in /scene/series
inline constexpr long kCelCheckpointVersion = 3;

struct CelCheckpoint {
  CelSolverState solver;
  SceneRunState run;
  std::vector<std::vector<double>> samples;  // rows of the caller's time series
};

// Writes to a temporary name and renames, so an interrupted write leaves the old file.
void write_cel_checkpoint(const std::filesystem::path& file, const CelSceneRun& run,
                          const std::vector<std::vector<double>>& samples);
// Throws std::runtime_error naming the file when it is not a CEL checkpoint of this version or
// does not fit `grid`.
CelCheckpoint read_cel_checkpoint(const std::filesystem::path& file, const CelGrid& grid);
// The run's state into and from an open file (no samples: the scene run loop keeps its series).
void write_cel_checkpoint(Hdf5File& file, const CelSceneRun& run);
CelCheckpoint read_cel_checkpoint(const Hdf5File& file, const CelGrid& grid);

}  // namespace feedflow::cel
