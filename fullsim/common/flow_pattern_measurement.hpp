#pragma once
// Mass or funnel flow of a hopper measured the same way on every rung: the speeds along a
// horizontal line across the converging section at mid-height (the CEL's node speeds, the
// DEM's particle speeds averaged in bins) from the centre line to the wall, sampled through
// the run and averaged over the steady discharge window. Mass flow when the material at the
// wall moves at more than a tenth of the centre line's speed (the whole content moves); funnel
// flow when it stands (a stagnant zone along the wall).
#include <cstddef>
#include <string>
#include <vector>

#include "fullsim/common/hdf5_file.hpp"

namespace feedflow {

// Speeds along the line, ordered from the centre line outwards.
struct SpeedProfile {
  std::vector<double> offset;  // distance from the centre line [m], ascending
  std::vector<double> speed;   // [m/s]
};

inline constexpr double kMassFlowSpeedRatio = 0.1;

struct WallSpeedRatio {
  double ratio = 0.0;          // wall speed / centre speed
  double stagnant_width = 0.0;  // [m] the band at the wall moving slower than a tenth of the centre
  bool measured = false;       // material on the line and a moving centre
  std::string label() const { return ratio > kMassFlowSpeedRatio ? "mass" : "funnel"; }
};

// Points a profile needs before it measures anything.
inline constexpr std::size_t kMinProfilePoints = 3;

// The speed of the outermost point over that of the innermost, and the dead zone's extent on
// the line: from the outermost point in to the outermost one that moves at more than a tenth of
// the innermost (0 when the outermost does). Not measured with fewer than kMinProfilePoints.
WallSpeedRatio wall_to_centre_speed_ratio(const SpeedProfile& line);

// The line sampled through a run: the ratio of its time-averaged profile over a window (each
// offset's mean speed over the samples that had material there; the outermost offset is the
// farthest one that had material in at least half of the window's samples, so a surface
// passing below the line late in the run does not count).
class SpeedProfileSeries {
 public:
  void add(double time, const SpeedProfile& line);
  WallSpeedRatio ratio(double from, double to) const;
  // The end of the part of [from, to] in which the line stayed under material: the time of the
  // last sample before the first one holding fewer than half the points of the window's fullest
  // sample (the falling surface, or a crater at the centre, has reached the line); `to` if none.
  double covered_until(double from, double to) const;
  std::size_t size() const { return time_.size(); }
  // Into and from `group` of a checkpoint (a restarted run averages over the whole run).
  void save(Hdf5File& file, const std::string& group) const;
  void restore(const Hdf5File& file, const std::string& group);

 private:
  // Sample k's points lie in offset_/speed_ from first_[k] up to end_of(k).
  std::size_t end_of(std::size_t k) const { return k + 1 < first_.size() ? first_[k + 1] : offset_.size(); }
  std::vector<double> time_;
  std::vector<std::size_t> first_;  // of each sample's points in offset_/speed_
  std::vector<double> offset_, speed_;
};

}  // namespace feedflow
