#pragma once
// Mass or funnel flow of a hopper measured the same way on every rung: the speeds along a
// horizontal line across the converging section at mid-height (the CEL's node speeds, the
// DEM's particle speeds averaged in bins) from the centre line to the wall. Mass flow when the
// material at the wall moves at more than a tenth of the centre line's speed (the whole
// content moves); funnel flow when it stands (a stagnant zone along the wall).
#include <string>
#include <vector>

namespace feedflow {

// Speeds along the line, ordered from the centre line outwards.
struct SpeedProfile {
  std::vector<double> offset;  // distance from the centre line [m], ascending
  std::vector<double> speed;   // [m/s]
};

inline constexpr double kMassFlowSpeedRatio = 0.1;

struct WallSpeedRatio {
  double ratio = 0.0;          // wall speed / centre speed
  bool measured = false;       // material on the line and a moving centre
  std::string label() const { return ratio > kMassFlowSpeedRatio ? "mass" : "funnel"; }
};

// The speed of the outermost point over that of the innermost.
WallSpeedRatio wall_to_centre_speed_ratio(const SpeedProfile& line);

}  // namespace feedflow
