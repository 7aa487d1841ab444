#pragma once
// A checkpoint of a CEL scene run (HDF5, format "feedflow CEL checkpoint" version 1, units on
// every dataset): the solver state (cell and node fields, counters, wall event times, discharge
// ledger), the scene run state (phase, event time, peak kinetic energy) and a table of the
// caller's samples so far. Reading it into a run built from the same scene continues
// bit-identically; a foreign, other-version or other-grid file is refused naming it.
#include <filesystem>
#include <vector>

#include "fullsim/cel/cel_scene_run.hpp"

namespace feedflow::cel {

inline constexpr const char* kCelCheckpointFormat = "feedflow CEL checkpoint";
inline constexpr long kCelCheckpointVersion = 2;  // 2: the turning frame's start

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
CelCheckpoint read_cel_checkpoint(const std::filesystem::path& file, const PlaneStrainGrid& grid);

}  // namespace feedflow::cel
