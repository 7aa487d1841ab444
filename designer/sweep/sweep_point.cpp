#include "designer/sweep/sweep_point.hpp"

#include <chrono>

#include "designer/design/design_check.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

std::vector<SetOverride> point_overrides(const SweepRequest& request,
                                         const std::vector<std::size_t>& index) {
  std::vector<SetOverride> sets = request.fixed;
  for (std::size_t k = 0; k < request.axes.size(); ++k)
    sets.push_back({request.axes[k].case_key, request.axes[k].values[index[k]].text});
  return sets;
}

SweepPoint answer_overrides(const SweepRequest& request, const std::vector<SetOverride>& sets) {
  const auto start = std::chrono::steady_clock::now();
  SweepPoint p;
  try {
    const Case c = load_case(request.parsed, sets, request.materials);
    DesignRecord r = design_check(c, request.models, DesignDetail::results);
    p.verdict = r.verdict.status;
    for (const auto& f : r.verdict.findings)
      if (f.limit && !f.quantity.empty()) p.limits.emplace_back(f.quantity, *f.limit);
    for (const auto& f : r.verdict.findings)
      if (f.status == p.verdict && !f.quantity.empty()) {
        if (p.governing.empty()) p.governing_reason = f.text;
        p.governing.push_back(f.quantity);
      }
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

SweepPoint answer_point(const SweepRequest& request, const std::vector<std::size_t>& index) {
  SweepPoint p = answer_overrides(request, point_overrides(request, index));
  p.index = index;
  return p;
}

}  // namespace feedflow
