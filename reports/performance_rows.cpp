#include "reports/performance_rows.hpp"

#include <algorithm>

#include "models/units/quantity_format.hpp"

namespace feedflow {

std::vector<PerformanceRow> performance_rows(const PerformanceBlock& b) {
  const auto time_text = [](double s) { return format_quantity(s, s < 1.0 ? "ms" : "s", 4); };
  const auto share = [&](double s) {
    return b.wall_seconds > 0.0 ? format_number(100.0 * s / b.wall_seconds, 3) + " %"
                                : std::string();
  };
  std::vector<PerformanceRow> rows{{"wall time", time_text(b.wall_seconds), ""}};
  for (const auto& [name, value] : b.figures) rows.push_back({name, value, ""});
  double booked = 0.0;
  for (const auto& [name, seconds] : b.phases) {
    rows.push_back({"phase: " + name, time_text(seconds), share(seconds)});
    booked += seconds;
  }
  if (!b.phases.empty()) {
    const double other = std::max(0.0, b.wall_seconds - booked);
    rows.push_back({"phase: other", time_text(other), share(other)});
  }
  return rows;
}

}  // namespace feedflow
