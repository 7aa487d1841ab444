#pragma once
// When a DEM drum run has converged, and its steady result. Samples are taken at a fixed
// interval after the shell starts; the angle, its band and the convergence are measured as on
// every rung (fullsim/common/steady_angle.hpp: spin-up left out, the start-up transient's
// batches dropped, the mean with its interval and 2 SD);
// beside them the bed state is averaged over the same windows, with the angle's peak-to-peak
// swing; the surface bulge is that of
// the time-averaged surface profile (column by column), so the snapshot noise of a coarse bed
// does not read as curvature. A bed without a free surface (centrifuging) has converged once
// the windows have passed.
#include <optional>
#include <string>
#include <vector>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/common/steady_angle.hpp"
#include "fullsim/dem/scene/drum_scene.hpp"

namespace feedflow {

struct DrumSteadyResult {
  double angle = 0.0;        // mean dynamic angle of repose [rad]
  double angle_sd = 0.0;     // standard deviation of the sampled angle [rad]
  double low = 0.0;          // mean - 2 SD [rad]
  double high = 0.0;         // mean + 2 SD [rad]
  DrumBedState state;        // averaged, with the angle's peak-to-peak swing
  std::size_t samples = 0;   // in the steady window
  std::string interval;      // the mean's confidence interval, in words (describe_interval)
  std::optional<double> interval_half_width;  // [rad] of that interval; none: < 2 batches
  std::vector<SurfacePoint> mean_surface;  // time-averaged surface profile [m]
  double from = 0.0;         // [s] window start (time since the shell started)
  double to = 0.0;           // [s]
};

class DrumAngleWatch {
 public:
  DrumAngleWatch(double drum_radius, double spin_up, double window, double tolerance)
      : radius_(drum_radius), windows_{spin_up, window, tolerance} {}

  void add(const DrumSample& sample) { samples_.push_back(sample); }
  bool converged() const;
  std::string converged_reason() const;  // "" until converged()
  // The result over the steady window (whatever has been sampled after the spin-up if the run
  // ends before converging); empty without samples after the spin-up.
  std::optional<DrumSteadyResult> steady() const;
  const std::vector<DrumSample>& samples() const { return samples_; }
  double spin_up() const { return windows_.spin_up; }
  double window() const { return windows_.window; }
  // Every sample, surface points included, into and from `group` of a checkpoint: a restarted
  // run measures exactly what the uninterrupted one does.
  void save(Hdf5File& file, const std::string& group) const;
  void restore(const Hdf5File& file, const std::string& group);

 private:
  std::vector<AngleSample> angles() const;

  double radius_;
  AngleWindows windows_;
  std::vector<DrumSample> samples_;
};

}  // namespace feedflow
