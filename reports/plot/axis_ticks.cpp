#include "reports/plot/axis_ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace feedflow {
namespace {

// The nice step nearest above `raw`: 1, 2, 2.5 or 5 times a power of ten.
double nice_step(double raw) {
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * magnitude >= raw * (1.0 - 1e-9)) return m * magnitude;
  return 10.0 * magnitude;
}

}  // namespace

std::string tick_label(double value, double step) {
  if (value == 0.0 || std::abs(value) < step * 1e-9) return "0";
  const double a = std::abs(value);
  char buf[48];
  if (a >= 1e6 || a < 1e-4) {
    // Scientific, with as many mantissa digits as the step needs.
    const int exponent = static_cast<int>(std::floor(std::log10(a)));
    const int digits = std::max(0, exponent - static_cast<int>(std::floor(std::log10(step))));
    std::snprintf(buf, sizeof buf, "%.*fe%d", std::min(digits, 6), value / std::pow(10.0, exponent), exponent);
    return buf;
  }
  int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  // A step like 2.5 or 0.25 needs one more decimal than its magnitude.
  const double scaled = step / std::pow(10.0, -decimals);
  if (std::abs(scaled - std::round(scaled)) > 1e-6) ++decimals;
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

double round_length_below(double limit) {
  const double decade = std::pow(10.0, std::floor(std::log10(limit)));
  for (const double m : {5.0, 2.0, 1.0})
    if (m * decade <= limit * (1.0 + 1e-12)) return m * decade;
  return decade;
}

std::vector<double> ticks_inside(double lo, double hi, int target) {
  if (!(hi > lo)) return {lo};
  const double step = round_length_below((hi - lo) / std::max(1, target - 1));
  std::vector<double> ticks;
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double t = first; t <= hi + 1e-9 * step; t = first + step * static_cast<double>(ticks.size()))
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

AxisTicks linear_ticks(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi))
    throw std::invalid_argument("axis ticks: the data range is not finite");
  if (lo > hi) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  const double step = nice_step((hi - lo) / std::max(1, target - 1));
  AxisTicks t;
  t.lower = std::floor(lo / step + 1e-9) * step;
  t.upper = std::ceil(hi / step - 1e-9) * step;
  const int count = static_cast<int>(std::lround((t.upper - t.lower) / step));
  for (int i = 0; i <= count; ++i) {
    const double v = t.lower + i * step;
    t.values.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
    t.labels.push_back(tick_label(t.values.back(), step));
  }
  return t;
}

AxisTicks log_ticks(double lo, double hi) {
  if (!(lo > 0.0) || !std::isfinite(hi))
    throw std::invalid_argument("logarithmic axis ticks need positive, finite data");
  if (lo > hi) std::swap(lo, hi);
  const int first = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  int last = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (last == first) ++last;
  AxisTicks t;
  t.lower = std::pow(10.0, first);
  t.upper = std::pow(10.0, last);
  for (int e = first; e <= last; ++e) {
    t.values.push_back(std::pow(10.0, e));
    char buf[16];
    std::snprintf(buf, sizeof buf, "1e%d", e);
    t.labels.push_back(e >= -3 && e <= 4 ? tick_label(t.values.back(), t.values.back()) : buf);
  }
  return t;
}

}  // namespace feedflow
