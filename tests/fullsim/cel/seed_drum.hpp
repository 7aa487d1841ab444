#pragma once
// The seed's drum for the CEL drum tests: 145 mm across, 202 mm long, half full, at `rpm`.
#include <numbers>

#include "models/equipment/drum.hpp"

namespace feedflow::cel {

inline Drum seed_drum(double rpm) {
  Drum drum;
  drum.diameter = 0.145;
  drum.length = 0.202;
  drum.fill_fraction = 0.5;
  drum.speed = rpm * 2.0 * std::numbers::pi / 60.0;
  return drum;
}

}  // namespace feedflow::cel
