#include "models/numerics/pareto_front.hpp"

#include <cmath>
#include <stdexcept>

namespace feedflow {

std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& error) {
  if (cost.size() != error.size()) throw std::invalid_argument("pareto_front: one cost per error");
  const std::size_t n = cost.size();
  std::vector<bool> on(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(cost[i]) || !std::isfinite(error[i])) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < n && !dominated; ++j) {
      if (j == i || !std::isfinite(cost[j]) || !std::isfinite(error[j])) continue;
      dominated = cost[j] <= cost[i] && error[j] <= error[i] && (cost[j] < cost[i] || error[j] < error[i]);
    }
    on[i] = !dominated;
  }
  return on;
}

}  // namespace feedflow
