#include "fullsim/common/flow_pattern_measurement.hpp"

namespace feedflow {

WallSpeedRatio wall_to_centre_speed_ratio(const SpeedProfile& line) {
  WallSpeedRatio r;
  if (line.speed.empty() || !(line.speed.front() > 0.0)) return r;
  r.ratio = line.speed.back() / line.speed.front();
  r.measured = true;
  return r;
}

}  // namespace feedflow
