#pragma once
// The small twin of the pilot hopper used by the CEL tests: the 30 deg wedge with a 0.3 m bin
// filled 0.35 m above the apex and a 60 mm outlet (pine on steel is 8.5 deg in the scenes).
#include "models/equipment/hopper.hpp"
#include "models/units/angle.hpp"

namespace feedflow::testing {

inline Hopper small_wedge() {
  Hopper h;
  h.shape = "wedge";
  h.semi_angle = 30.0 * kDegree;
  h.outlet_width = 0.06;
  h.fill_height = 0.35;
  h.bin_width = 0.3;
  return h;
}

}  // namespace feedflow::testing
