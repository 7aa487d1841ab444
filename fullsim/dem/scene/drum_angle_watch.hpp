#pragma once
// When a drum run has converged, and its steady result. Samples are taken at a fixed interval
// after the shell starts; the first `spin_up` seconds are the bed being lifted to its dynamic
// angle and are not used. The run has converged when the mean angle of the last `window`
// seconds and of the window before differ by less than `tolerance`; the steady result is over
// those two windows: the mean angle with a band of two standard deviations of the sampled
// angle (the surface fluctuates: the band says how far one snapshot may lie from the mean),
// and the averaged bed state with the angle's peak-to-peak swing; the surface bulge is that of
// the time-averaged surface profile (column by column), so the snapshot noise of a coarse bed
// does not read as curvature. A bed without a free surface (centrifuging) has converged once
// the windows have passed.
#include <optional>
#include <vector>

#include "fullsim/dem/scene/drum_scene.hpp"

namespace feedflow {

struct DrumSteadyResult {
  double angle = 0.0;        // mean dynamic angle of repose [rad]
  double angle_sd = 0.0;     // standard deviation of the sampled angle [rad]
  double low = 0.0;          // mean - 2 SD [rad]
  double high = 0.0;         // mean + 2 SD [rad]
  DrumBedState state;        // averaged, with the angle's peak-to-peak swing
  std::size_t samples = 0;   // in the two windows
  std::vector<SurfacePoint> mean_surface;  // time-averaged surface profile [m]
  double from = 0.0;         // [s] window start (time since the shell started)
  double to = 0.0;           // [s]
};

class DrumAngleWatch {
 public:
  DrumAngleWatch(double drum_radius, double spin_up, double window, double tolerance)
      : radius_(drum_radius), spin_up_(spin_up), window_(window), tolerance_(tolerance) {}

  void add(const DrumSample& sample) { samples_.push_back(sample); }
  bool converged() const;
  // The result over the last two windows after the spin-up (whatever has been sampled there if
  // the run ends before converging); empty without samples after the spin-up.
  std::optional<DrumSteadyResult> steady() const;
  const std::vector<DrumSample>& samples() const { return samples_; }
  double spin_up() const { return spin_up_; }
  double window() const { return window_; }

 private:
  double radius_, spin_up_, window_, tolerance_;
  std::vector<DrumSample> samples_;
};

}  // namespace feedflow
