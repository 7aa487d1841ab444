#include "fullsim/common/run_report.hpp"

#include <algorithm>
#include <cstdio>

#include "models/units/quantity_format.hpp"

namespace feedflow {

RunReport::RunReport(std::string title) : title_(std::move(title)), start_(Clock::now()) {}

RunReport::PhaseScope::PhaseScope(RunReport& report, std::string_view phase)
    : report_(report), index_(report.phase_index(phase)), start_(Clock::now()) {}

RunReport::PhaseScope::~PhaseScope() {
  report_.phases_[index_].second += std::chrono::duration<double>(Clock::now() - start_).count();
}

std::size_t RunReport::phase_index(std::string_view phase) {
  for (std::size_t i = 0; i < phases_.size(); ++i)
    if (phases_[i].first == phase) return i;
  phases_.emplace_back(std::string(phase), 0.0);
  return phases_.size() - 1;
}

void RunReport::add_phase_time(std::string_view phase, double seconds) {
  phases_[phase_index(phase)].second += seconds;
}

void RunReport::add_figure(std::string name, std::string value) {
  figures_.emplace_back(std::move(name), std::move(value));
}

double RunReport::wall_seconds() const {
  if (wall_override_ >= 0.0) return wall_override_;
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

double RunReport::phase_seconds(std::string_view phase) const {
  for (const auto& [name, seconds] : phases_)
    if (name == phase) return seconds;
  return 0.0;
}

std::string RunReport::render() const {
  const double wall = wall_seconds();
  std::string out = "Performance: " + title_ + "\n";
  char line[160];
  auto time_text = [](double s) { return format_quantity(s, s < 1.0 ? "ms" : "s", 4); };
  std::snprintf(line, sizeof line, "  %-28s %s\n", "wall time", time_text(wall).c_str());
  out += line;
  for (const auto& [name, value] : figures_) {
    std::snprintf(line, sizeof line, "  %-28s %s\n", name.c_str(), value.c_str());
    out += line;
  }
  if (phases_.empty()) return out;
  std::snprintf(line, sizeof line, "  %-28s %12s %8s\n", "phase", "time", "share");
  out += line;
  double booked = 0.0;
  auto add_row = [&](const std::string& name, double seconds) {
    const double share = wall > 0 ? 100.0 * seconds / wall : 0.0;
    std::snprintf(line, sizeof line, "  %-28s %12s %6.1f %%\n", name.c_str(),
                  time_text(seconds).c_str(), share);
    out += line;
  };
  for (const auto& [name, seconds] : phases_) {
    add_row(name, seconds);
    booked += seconds;
  }
  add_row("other", std::max(0.0, wall - booked));
  return out;
}

}  // namespace feedflow
