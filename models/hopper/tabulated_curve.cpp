#include "models/hopper/tabulated_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace feedflow {

TabulatedCurve::TabulatedCurve(std::vector<double> x, std::vector<double> y, Beyond beyond)
    : x_(std::move(x)), y_(std::move(y)), beyond_(beyond) {
  if (x_.size() != y_.size())
    throw std::invalid_argument("table needs as many values as abscissae");
  if (x_.size() < 2) throw std::invalid_argument("table needs at least 2 points");
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      throw std::invalid_argument("table entries must be finite numbers");
    if (i > 0 && !(x_[i] > x_[i - 1]))
      throw std::invalid_argument("table abscissae must increase strictly");
  }
}

double TabulatedCurve::operator()(double x) const {
  if (beyond_ == Beyond::hold_end_values) {
    if (x <= x_.front()) return y_.front();
    if (x >= x_.back()) return y_.back();
  }
  // Segment [i-1, i] containing x (the first or last segment outside the points).
  auto it = std::upper_bound(x_.begin(), x_.end(), x);
  std::size_t i = static_cast<std::size_t>(it - x_.begin());
  i = std::clamp<std::size_t>(i, 1, x_.size() - 1);
  const double w = (x - x_[i - 1]) / (x_[i] - x_[i - 1]);
  return y_[i - 1] + w * (y_[i] - y_[i - 1]);
}

}  // namespace feedflow
