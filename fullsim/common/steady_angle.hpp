#pragma once
// The dynamic angle of repose of a turning drum measured the same way on every rung, from the
// sampled angle of its free surface. The samples of the first `spin_up` seconds (the bed being
// lifted) are left out; the rest is cut into batches of `window` seconds, and MSER truncation
// drops the batches of the start-up transient (the first avalanche overshoots the steady angle
// by up to 25 deg and takes about a turn to settle). The steady angle is the mean over the kept
// batches, with the confidence interval of that mean from the batch means (Student t) and a band
// of two standard deviations of the sampled angle (the surface fluctuates: the band says how far
// one snapshot may lie from the mean). The run has converged when at least `min_batches` are
// kept and the interval's half-width is within `tolerance`.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace feedflow {

struct AngleSample {
  double time = 0.0;   // [s] since the shell started
  double angle = 0.0;  // [rad]
  bool valid = false;  // a surface line could be fitted
};

struct AngleWindows {
  double spin_up = 0.5;         // [s]
  double window = 0.5;          // [s] one batch
  double tolerance = 0.0;       // [rad] half-width of the mean's confidence interval
  std::size_t min_batches = 5;  // kept after the transient
  double confidence = 0.95;
};

// A drum turning at `speed` [rad/s]: spin-up 0.15 and batches 0.1 of a revolution, at least
// 0.5 s each; converged within +-1 deg (95 %) over at least 5 batches.
AngleWindows drum_angle_windows(double speed);

struct SteadyAngle {
  bool found = false;            // valid samples after the spin-up
  bool converged = false;        // >= min_batches kept and the interval within the tolerance
  double angle = 0.0;            // mean [rad]
  double sd = 0.0;               // standard deviation of the sampled angle [rad]
  double low = 0.0, high = 0.0;  // mean -+ 2 SD [rad]
  double ci_low = 0.0,
         ci_high = 0.0;         // confidence interval of the mean [rad] (the band when < 2 batches)
  double swing = 0.0;           // peak to peak [rad]
  double from = 0.0, to = 0.0;  // the window [s]
  std::size_t batches = 0;      // kept batches
  std::size_t dropped = 0;      // batches of the transient dropped
  std::size_t samples = 0;      // all samples in the window (valid or not)
  std::size_t valid = 0;        // valid ones
};

// Whether the angle has converged (steady_angle's `converged`); a bed without a free surface
// (fewer than three valid samples in both of the last two windows: it turns with the shell) has
// converged once they have passed.
bool angle_converged(const std::vector<AngleSample>& samples, const AngleWindows& w);
// Over the batches after the spin-up that MSER keeps (whatever has been sampled after the
// spin-up if fewer than two batches are complete).
SteadyAngle steady_angle(const std::vector<AngleSample>& samples, const AngleWindows& w);

// For the results and the run's end: "95 % interval of the mean +-1.6 deg over 10 batches, 6 of
// the transient dropped", and why a run stopped: "converged: ...".
std::string describe_interval(const SteadyAngle& a, const AngleWindows& w);
// The half-width of the mean's confidence interval [rad]; none with fewer than two batches.
std::optional<double> interval_half_width(const SteadyAngle& a);
std::string converged_reason(const std::vector<AngleSample>& samples, const AngleWindows& w);

}  // namespace feedflow
