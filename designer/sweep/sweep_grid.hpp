#pragma once
// A sweep's design points, answered in this process (no process per point, no charts), shared
// among the OpenMP threads: every combination of the axes' values (a grid), or with a sampled
// sweep the n-th value of every axis for point n. With --solve-for each point is a solve.
#include <vector>

#include "designer/sweep/sweep_point.hpp"
#include "fullsim/common/progress_sink.hpp"

namespace feedflow {

// Points in the grid (the product of the axes' sizes; 1 without axes).
std::size_t grid_size(const std::vector<SweepAxis>& axes);
// The axis values of grid point `n` (the last axis varies fastest).
std::vector<std::size_t> grid_index(const std::vector<SweepAxis>& axes, std::size_t n);

// The request's points: the grid, or one per sample.
std::size_t point_count(const SweepRequest& request);
std::vector<std::size_t> point_index(const SweepRequest& request, std::size_t n);

// Answers (or solves) every point on the OpenMP threads, reporting progress in points.
std::vector<SweepPoint> run_grid(const SweepRequest& request, ProgressSink& progress);

}  // namespace feedflow
