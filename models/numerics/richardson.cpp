#include "models/numerics/richardson.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace feedflow {
namespace {

constexpr double kSafetyThreeLevels = 1.25;
constexpr double kSafetyTwoLevels = 3.0;

void check_finite(const double* f, int n) {
  for (int k = 0; k < n; ++k)
    if (!std::isfinite(f[k])) throw std::invalid_argument("richardson: a value is not finite");
}

}  // namespace

RichardsonEstimate richardson(const std::array<double, 3>& h, const std::array<double, 3>& f) {
  check_finite(f.data(), 3);
  if (!(h[0] > h[1] && h[1] > h[2] && h[2] > 0.0))
    throw std::invalid_argument("richardson: the resolutions must shrink (h1 > h2 > h3 > 0)");
  const double r = h[0] / h[1];
  if (std::abs(h[1] / h[2] - r) > 1e-6 * r)
    throw std::invalid_argument("richardson: the resolutions must shrink by one ratio");
  const double e21 = f[1] - f[0], e32 = f[2] - f[1];
  RichardsonEstimate out;
  if (e21 != 0.0 && e32 != 0.0 && (e21 > 0.0) == (e32 > 0.0)) {
    const double p = std::log(e21 / e32) / std::log(r);
    if (p > 0.0) {
      const double grow = std::pow(r, p) - 1.0;
      out.order = p;
      out.value = f[2] + e32 / grow;
      out.error_bar = kSafetyThreeLevels * std::abs(e32) / grow;
      out.asymptotic = p >= 0.5 && p <= 8.0;
      return out;
    }
  }
  // Not converging monotonically: the finest value, with the spread of the three.
  out.diverging = e21 != 0.0 && e32 != 0.0 && (e21 > 0.0) == (e32 > 0.0);
  out.value = f[2];
  out.error_bar = std::max({std::abs(e21), std::abs(e32), std::abs(f[2] - f[0])});
  return out;
}

RichardsonEstimate richardson_two_levels(const std::array<double, 2>& h, const std::array<double, 2>& f,
                                         double formal_order) {
  check_finite(f.data(), 2);
  if (!(h[0] > h[1] && h[1] > 0.0)) throw std::invalid_argument("richardson: the resolutions must shrink");
  if (!(formal_order > 0.0)) throw std::invalid_argument("richardson: the formal order must be > 0");
  const double grow = std::pow(h[0] / h[1], formal_order) - 1.0;
  RichardsonEstimate out;
  out.value = f[1] + (f[1] - f[0]) / grow;
  out.error_bar = kSafetyTwoLevels * std::abs(f[1] - f[0]) / grow;
  return out;
}

}  // namespace feedflow
