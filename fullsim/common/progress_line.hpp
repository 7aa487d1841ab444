#pragma once
// The one-line progress display of long runs: fraction done, elapsed time and an ETA, redrawn
// in place on a terminal. Silent when the stream is not a terminal or when asked to be quiet.
#include <chrono>
#include <functional>
#include <optional>
#include <ostream>
#include <string>

#include "fullsim/common/progress_sink.hpp"

namespace feedflow {

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;

  // `total` is the amount of work in `unit` (e.g. 2 simulated seconds, unit "s").
  ProgressLine(std::string label, double total, std::string unit, std::ostream& out,
               bool enabled);
  // Enabled when stderr is a terminal and not quiet.
  static ProgressLine for_terminal(std::string label, double total, std::string unit, bool quiet);
  ~ProgressLine();

  // Reports the amount done; redraws at most every `min_interval` (default 0.2 s).
  void update(double done);
  // Clears the line.
  void finish();

  // Estimated remaining wall time after `elapsed` seconds with `fraction` done (linear
  // extrapolation); negative when unknown.
  static double eta_seconds(double elapsed, double fraction);
  // The text of the line for the given state (no carriage return).
  std::string render(double done, double elapsed) const;

  // For tests: a clock to use instead of the steady clock, and the redraw interval.
  void set_clock(std::function<Clock::time_point()> now) { now_ = std::move(now); start_ = now_(); }
  void set_min_interval(double seconds) { min_interval_ = seconds; }

 private:
  std::string label_;
  double total_;
  std::string unit_;
  std::ostream& out_;
  bool enabled_;
  bool drawn_ = false;
  double min_interval_ = 0.2;
  std::function<Clock::time_point()> now_;
  Clock::time_point start_;
  Clock::time_point last_draw_;
  std::size_t last_width_ = 0;
};

// The progress sink of a terminal: one ProgressLine per stretch of work, shown on `out` when
// enabled (for_terminal(): stderr is a terminal and the run is not quiet).
class TerminalProgress final : public ProgressSink {
 public:
  TerminalProgress(std::ostream& out, bool enabled) : out_(out), enabled_(enabled) {}
  static TerminalProgress for_terminal(bool quiet);
  void begin(const std::string& label, double total, const std::string& unit) override;
  void update(double done) override;
  void finish() override;

 private:
  std::ostream& out_;
  bool enabled_;
  std::optional<ProgressLine> line_;
};

// "1 h 02 min", "3 min 05 s", "12 s"
std::string format_duration(double seconds);

}  // namespace feedflow
