#pragma once
// The performance block that ends every long run: wall time, throughput figures and the time
// spent in each phase (as LAMMPS prints its timing breakdown).
#include <chrono>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace feedflow {

class RunReport {
 public:
  using Clock = std::chrono::steady_clock;

  explicit RunReport(std::string title);

  // Adds the time between construction and destruction of the scope to `phase`.
  class PhaseScope {
   public:
    PhaseScope(RunReport& report, std::string_view phase);
    ~PhaseScope();
    PhaseScope(const PhaseScope&) = delete;
    PhaseScope& operator=(const PhaseScope&) = delete;

   private:
    RunReport& report_;
    std::size_t index_;
    Clock::time_point start_;
  };
  PhaseScope time(std::string_view phase) { return PhaseScope(*this, phase); }

  void add_phase_time(std::string_view phase, double seconds);
  // A throughput or size figure, already formatted with its unit ("1.2e6 particle-steps/s").
  void add_figure(std::string name, std::string value);
  // Wall time of the run; by default the time since construction.
  void set_wall_seconds(double seconds) { wall_override_ = seconds; }
  double wall_seconds() const;
  double phase_seconds(std::string_view phase) const;

  // The block, ending in a newline. Time not booked to any phase is shown as "other".
  std::string render() const;

  const std::string& title() const { return title_; }
  const std::vector<std::pair<std::string, double>>& phases() const { return phases_; }
  const std::vector<std::pair<std::string, std::string>>& figures() const { return figures_; }

 private:
  std::size_t phase_index(std::string_view phase);

  std::string title_;
  Clock::time_point start_;
  double wall_override_ = -1.0;
  std::vector<std::pair<std::string, double>> phases_;
  std::vector<std::pair<std::string, std::string>> figures_;
};

}  // namespace feedflow
