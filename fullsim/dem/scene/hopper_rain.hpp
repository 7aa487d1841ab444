#pragma once
// The rain fill of a hopper scene (a wedge slab or a cone): spheres rain from a region riding
// 30 mm above the resting fill at 0.5 m/s, at a rate that fills the hopper in about 0.6 s, to
// 20 % more than the estimated fill (so the trim at the fill top leaves a level surface), until
// the fill comes within reach of the wall top; settled to rest or 0.5 s, trimmed at the fill
// top, and banded in `bands` equal layers from the outlet plane for the flow pattern.
#include <cstdint>
#include <functional>

#include "fullsim/dem/scene/rain_fill.hpp"

namespace feedflow {

struct HopperRain {
  Vec3 region_lower, region_upper;  // the region's box at the start [m]
  double radius = 0.0;              // of the spheres [m]
  double density = 0.0;             // [kg/m^3]
  double fill_mass = 0.0;           // the estimated fill [kg]
  double fill_top = 0.0;            // above the outlet [m]
  double wall_top = 0.0;            // the walls' top [m]
  int bands = 1;
  std::uint64_t seed = 1;
  std::function<bool(const Vec3&, double)> admits;  // centres inside the container
};

RainFillSettings hopper_rain_settings(const HopperRain& h);

}  // namespace feedflow
