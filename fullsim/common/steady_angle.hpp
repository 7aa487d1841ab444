#pragma once
// The dynamic angle of repose of a turning drum measured the same way on every rung, from the
// sampled angle of its free surface: the samples of the first `spin_up` seconds (the bed being
// lifted to its angle) are left out; the run has converged when the mean angle of the last
// `window` and of the window before differ by less than `tolerance`; the steady angle is the
// mean over those two windows, with a band of two standard deviations of the sampled angle
// (the surface fluctuates: the band says how far one snapshot may lie from the mean).
#include <cstddef>
#include <vector>

namespace feedflow {

struct AngleSample {
  double time = 0.0;   // [s] since the shell started
  double angle = 0.0;  // [rad]
  bool valid = false;  // a surface line could be fitted
};

struct AngleWindows {
  double spin_up = 0.5;    // [s]
  double window = 0.5;     // [s]
  double tolerance = 0.0;  // [rad]
};

// A drum turning at `speed` [rad/s]: spin-up 0.15 and window 0.1 of a revolution, at least
// 0.5 s each; tolerance 1 deg.
AngleWindows drum_angle_windows(double speed);

struct SteadyAngle {
  bool found = false;          // valid samples after the spin-up
  double angle = 0.0;          // mean [rad]
  double sd = 0.0;             // standard deviation of the sampled angle [rad]
  double low = 0.0, high = 0.0;  // mean -+ 2 SD [rad]
  double swing = 0.0;          // peak to peak [rad]
  double from = 0.0, to = 0.0; // the window [s]
  std::size_t samples = 0;     // all samples in the window (valid or not)
  std::size_t valid = 0;       // valid ones
};

// Whether the two last windows agree; a bed without a free surface (fewer than three valid
// samples in both windows: it turns with the shell) has converged once they have passed.
bool angle_converged(const std::vector<AngleSample>& samples, const AngleWindows& w);
// Over the last two windows after the spin-up (whatever has been sampled there if the run ends
// before converging).
SteadyAngle steady_angle(const std::vector<AngleSample>& samples, const AngleWindows& w);

}  // namespace feedflow
