#include "designer/sweep/sweep_grid.hpp"

#include <atomic>
#include <chrono>

#include "designer/design/design_check.hpp"
#include "models/core/errors.hpp"

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

std::vector<SetOverride> point_overrides(const SweepRequest& request,
                                         const std::vector<std::size_t>& index) {
  std::vector<SetOverride> sets = request.fixed;
  for (std::size_t k = 0; k < request.axes.size(); ++k)
    sets.push_back({request.axes[k].case_key, request.axes[k].values[index[k]].text});
  return sets;
}

SweepPoint answer_point(const SweepRequest& request, const std::vector<std::size_t>& index) {
  const auto start = std::chrono::steady_clock::now();
  SweepPoint p;
  p.index = index;
  try {
    const std::vector<SetOverride> sets = point_overrides(request, index);
    const Case c = load_case(request.parsed, sets, request.materials);
    DesignRecord r = design_check(c, request.models, DesignDetail::results);
    p.verdict = r.verdict.status;
    for (const auto& f : r.verdict.findings)
      if (f.status == p.verdict && !f.quantity.empty()) p.governing.push_back(f.quantity);
    p.results = std::move(r.results);
    for (auto& [key, e] : p.results) e.model.clear();
    p.done = true;
  } catch (const InputError& e) {
    p.error = e.what();
  } catch (const std::exception& e) {  // a model that cannot answer at this point
    p.error = e.what();
  }
  p.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return p;
}

std::vector<SweepPoint> run_grid(const SweepRequest& request, ProgressSink& progress) {
  const std::size_t n = grid_size(request.axes);
  std::vector<SweepPoint> points(n);
  progress.begin("sweep", static_cast<double>(n), "points");
  std::atomic<std::size_t> finished{0};
  std::size_t shown = 0;  // the progress line only moves forward
#pragma omp parallel for schedule(dynamic, 16)
  for (std::size_t i = 0; i < n; ++i) {
    points[i] = answer_point(request, grid_index(request.axes, i));
    const std::size_t done = ++finished;
    if (done % 256 == 0) {
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
