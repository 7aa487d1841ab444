#include "reports/render/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace feedflow::render {

double round_length_below(double limit) {
  const double decade = std::pow(10.0, std::floor(std::log10(limit)));
  for (double m : {5.0, 2.0, 1.0}) {
    if (m * decade <= limit * (1.0 + 1e-12)) return m * decade;
  }
  return decade;
}

std::vector<double> round_ticks(double lo, double hi, int target) {
  if (!(hi > lo)) return {lo};
  const double step = round_length_below((hi - lo) / std::max(1, target - 1));
  std::vector<double> ticks;
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double t = first; t <= hi + 1e-9 * step;
       t = first + step * static_cast<double>(ticks.size())) {
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

std::string tick_label(double value, double step) {
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 9);
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace feedflow::render
