#pragma once
// A sweep's grid of design points, each answered in this process by the design check on the
// reduced rungs (no process per point, no charts), the points shared among the OpenMP threads.
// A point whose values the case loader refuses (a semi-angle past the wall, an outlet wider
// than the bin) is kept with its reason and the sweep goes on.
#include <string>
#include <vector>

#include "designer/case/case_loader.hpp"
#include "designer/case/material_library.hpp"
#include "designer/design/model_choices.hpp"
#include "designer/sweep/sweep_axis.hpp"
#include "fullsim/common/progress_sink.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

struct SweepRequest {
  ParsedCase parsed;               // the case file, parsed once
  std::vector<SetOverride> fixed;  // the --set values every point takes
  std::vector<SweepAxis> axes;     // the --vary keys, the first varying slowest
  ModelChoices models;
  MaterialLibrary materials{{}};
};

struct SweepPoint {
  std::vector<std::size_t> index;  // the value of each axis
  bool done = false;               // answered; else `error` says why not
  std::string error;
  VerdictStatus verdict = VerdictStatus::unknown;
  std::vector<std::string> governing;  // the quantities of the findings at the verdict's status
  Estimates results;                   // without the model texts
  double wall_seconds = 0.0;
};

// Points in the grid (the product of the axes' sizes).
std::size_t grid_size(const std::vector<SweepAxis>& axes);
// The axis values of grid point `n` (the last axis varies fastest).
std::vector<std::size_t> grid_index(const std::vector<SweepAxis>& axes, std::size_t n);

// The overrides of one point: the fixed ones, then each axis at its value.
std::vector<SetOverride> point_overrides(const SweepRequest& request,
                                         const std::vector<std::size_t>& index);

// Answers one point (never throws for the point's own values: a refused point is `done = false`).
SweepPoint answer_point(const SweepRequest& request, const std::vector<std::size_t>& index);

// Answers every grid point on the OpenMP threads, reporting progress in points.
std::vector<SweepPoint> run_grid(const SweepRequest& request, ProgressSink& progress);

}  // namespace feedflow
