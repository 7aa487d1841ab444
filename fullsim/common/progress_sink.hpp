#pragma once
// Where a long run reports how far it has come: a terminal line with an ETA
// (progress_line.hpp), or nothing. Engines and the scene run loop only call this.
#include <string>

namespace feedflow {

class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  // A new stretch of work: `total` in `unit` (e.g. 2 simulated seconds, "s").
  virtual void begin(const std::string& label, double total, const std::string& unit) = 0;
  virtual void update(double done) = 0;
  virtual void finish() = 0;
};

// The sink that shows nothing.
class SilentProgress final : public ProgressSink {
 public:
  void begin(const std::string&, double, const std::string&) override {}
  void update(double) override {}
  void finish() override {}
};

}  // namespace feedflow
