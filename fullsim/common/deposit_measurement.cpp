#include "fullsim/common/deposit_measurement.hpp"

#include <algorithm>
#include <cmath>

namespace feedflow {

DepositThickness mid_ramp_thickness(const std::vector<double>& x, const std::vector<double>& thickness,
                                    double ramp_length, double half_window) {
  DepositThickness d;
  double sum = 0.0;
  for (std::size_t k = 0; k < x.size() && k < thickness.size(); ++k)
    if (std::abs(x[k] - 0.5 * ramp_length) <= half_window * ramp_length) {
      d.low = d.points ? std::min(d.low, thickness[k]) : thickness[k];
      d.high = d.points ? std::max(d.high, thickness[k]) : thickness[k];
      sum += thickness[k];
      ++d.points;
    }
  d.value = d.points ? sum / static_cast<double>(d.points) : 0.0;
  return d;
}

}  // namespace feedflow
