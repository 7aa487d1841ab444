#include "designer/sweep/sweep_grid.hpp"

#include <atomic>

#include "designer/sweep/sweep_solve.hpp"

namespace feedflow {

std::size_t grid_size(const std::vector<SweepAxis>& axes) {
  std::size_t n = 1;
  for (const auto& a : axes) n *= a.values.size();
  return n;
}

std::vector<std::size_t> grid_index(const std::vector<SweepAxis>& axes, std::size_t n) {
  std::vector<std::size_t> index(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {
    index[k] = n % axes[k].values.size();
    n /= axes[k].values.size();
  }
  return index;
}

std::size_t point_count(const SweepRequest& request) {
  if (request.sampled) return request.axes.empty() ? 1 : request.axes.front().values.size();
  return grid_size(request.axes);
}

std::vector<std::size_t> point_index(const SweepRequest& request, std::size_t n) {
  if (request.sampled) return std::vector<std::size_t>(request.axes.size(), n);
  return grid_index(request.axes, n);
}

std::vector<SweepPoint> run_grid(const SweepRequest& request, ProgressSink& progress) {
  const std::size_t n = point_count(request);
  std::vector<SweepPoint> points(n);
  progress.begin(request.solve ? "solve" : "sweep", static_cast<double>(n), "points");
  std::atomic<std::size_t> finished{0};
  std::size_t shown = 0;  // the progress line only moves forward
  // A solve is tens of design checks: report every point then.
  const std::size_t every = request.solve ? 1 : 256;
#pragma omp parallel for schedule(dynamic, request.solve ? 1 : 16)
  for (std::size_t i = 0; i < n; ++i) {
    const auto index = point_index(request, i);
    points[i] = request.solve ? solve_point(request, index) : answer_point(request, index);
    const std::size_t done = ++finished;
    if (done % every == 0) {
#pragma omp critical(sweep_progress)
      if (done > shown) {
        shown = done;
        progress.update(static_cast<double>(done));
      }
    }
  }
  progress.update(static_cast<double>(n));
  progress.finish();
  return points;
}

}  // namespace feedflow
