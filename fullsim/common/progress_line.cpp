#include "fullsim/common/progress_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "models/units/quantity_format.hpp"

namespace feedflow {

ProgressLine::ProgressLine(std::string label, double total, std::string unit, std::ostream& out,
                           bool enabled)
    : label_(std::move(label)),
      total_(total),
      unit_(std::move(unit)),
      out_(out),
      enabled_(enabled),
      now_([] { return Clock::now(); }),
      start_(now_()),
      last_draw_(start_) {}

ProgressLine ProgressLine::for_terminal(std::string label, double total, std::string unit,
                                        bool quiet) {
  return ProgressLine(std::move(label), total, std::move(unit), std::cerr,
                      !quiet && isatty(STDERR_FILENO) == 1);
}

ProgressLine::~ProgressLine() { finish(); }

TerminalProgress TerminalProgress::for_terminal(bool quiet) {
  return TerminalProgress(std::cerr, !quiet && isatty(STDERR_FILENO) == 1);
}

void TerminalProgress::begin(const std::string& label, double total, const std::string& unit) {
  if (line_) line_->finish();
  line_.emplace(label, total, unit, out_, enabled_);
}

void TerminalProgress::update(double done) {
  if (line_) line_->update(done);
}

void TerminalProgress::finish() {
  if (line_) line_->finish();
  line_.reset();
}

double ProgressLine::eta_seconds(double elapsed, double fraction) {
  if (!(fraction > 0.0) || !std::isfinite(elapsed)) return -1.0;
  if (fraction >= 1.0) return 0.0;
  return elapsed * (1.0 - fraction) / fraction;
}

std::string format_duration(double seconds) {
  if (seconds < 0) return "--";
  const long s = std::lround(seconds);
  char buf[48];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  else if (s >= 60)
    std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld s", s);
  return buf;
}

std::string ProgressLine::render(double done, double elapsed) const {
  const double fraction = total_ > 0 ? std::clamp(done / total_, 0.0, 1.0) : 0.0;
  char percent[16];
  std::snprintf(percent, sizeof percent, "%5.1f %%", 100.0 * fraction);
  return label_ + "  " + percent + "  " + format_number(done) + " / " +
         format_quantity(total_, unit_) + "  elapsed " + format_duration(elapsed) + "  ETA " +
         format_duration(eta_seconds(elapsed, fraction));
}

void ProgressLine::update(double done) {
  if (!enabled_) return;
  const auto now = now_();
  if (drawn_ && std::chrono::duration<double>(now - last_draw_).count() < min_interval_) return;
  last_draw_ = now;
  const std::string line = render(done, std::chrono::duration<double>(now - start_).count());
  out_ << '\r' << line;
  if (line.size() < last_width_) out_ << std::string(last_width_ - line.size(), ' ');
  out_.flush();
  last_width_ = line.size();
  drawn_ = true;
}

void ProgressLine::finish() {
  if (!enabled_ || !drawn_) return;
  out_ << '\r' << std::string(last_width_, ' ') << '\r';
  out_.flush();
  drawn_ = false;
}

}  // namespace feedflow
