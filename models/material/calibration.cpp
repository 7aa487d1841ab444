#include "models/material/calibration.hpp"

#include <algorithm>
#include <cstdlib>
#include <string_view>

namespace feedflow {

std::optional<double> percent_figure(const CalibratedModel& m, const std::string& name) {
  const auto it = m.figures.find(name);
  if (it == m.figures.end()) return std::nullopt;
  const std::string& text = it->second;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end == text.c_str()) return std::nullopt;
  while (*end == ' ') ++end;
  if (std::string_view(end) != "%") return std::nullopt;
  return x / 100.0;
}

std::optional<double> largest_error(const CalibratedModel& m) {
  std::optional<double> error;
  for (const char* figure : {"fit_rms_error", "held_out_max_error"})
    if (const auto x = percent_figure(m, figure)) error = std::max(error.value_or(*x), *x);
  return error;
}

}  // namespace feedflow
