#include "fullsim/dem/scene/hopper_rain.hpp"

#include <algorithm>

namespace feedflow {
namespace {

constexpr double kHopperFollowGap = 0.03;  // [m] drop height over the resting fill
constexpr double kFillDuration = 0.6;  // [s] the rate fills the hopper in about this time

}  // namespace

RainFillSettings hopper_rain_settings(const HopperRain& h) {
  RainFillSettings s;
  s.region_lower = h.region_lower;
  s.region_upper = h.region_upper;
  s.follow_gap = kHopperFollowGap;
  s.radius = h.radius;
  s.density = h.density;
  s.mass_rate = h.fill_mass / kFillDuration;
  s.target_mass = kRainSurplus * h.fill_mass;
  s.initial_velocity = Vec3(0, 0, -kRainSpeed);
  s.insert_time_cap = 6.0 * kFillDuration + 2.0;
  s.settle_time_cap = 0.5;
  // The region rides kHopperFollowGap over the resting fill and admits() stops it at the wall top:
  // once the fill comes that close nothing more can be placed, so inserting ends there instead of
  // idling to the time cap (the pilot slab's 20 % surplus does not fit under its wall top).
  s.target_height = h.wall_top - kHopperFollowGap - 2.0 * h.radius;
  s.trim_height = h.fill_top;
  s.band_origin = 0.0;
  s.band_height = h.fill_top / std::max(1, h.bands);
  s.seed = h.seed;
  s.admits = h.admits;
  return s;
}

}  // namespace feedflow
