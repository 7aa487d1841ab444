#pragma once
// The box of a DEM run: the cell grid spans it; along a periodic axis it repeats (minimum-image
// distances, positions wrapped at neighbour-list rebuilds). Along the other axes particles may
// leave it (walls or the outlet sink hold or remove them); they are binned in the edge cells.
#include <array>
#include <cmath>

#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

struct SimulationBox {
  Vec3 lower = Vec3::Zero();  // [m]
  Vec3 upper = Vec3::Ones();  // [m]
  std::array<bool, 3> periodic{false, false, false};

  Vec3 length() const { return upper - lower; }
  bool any_periodic() const { return periodic[0] || periodic[1] || periodic[2]; }

  // The shortest image of a separation vector of two positions no farther than 1.5 box
  // lengths apart along each periodic axis (positions are wrapped at every rebuild and move
  // less than the skin between rebuilds). No division: this runs once per listed pair.
  Vec3 minimum_image(Vec3 d) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) {
        const double l = upper[a] - lower[a];
        if (d[a] > 0.5 * l) d[a] -= l;
        else if (d[a] < -0.5 * l) d[a] += l;
      }
    return d;
  }
  // The position brought into [lower, upper) along the periodic axes.
  Vec3 wrap(Vec3 x) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) {
        const double l = upper[a] - lower[a];
        x[a] -= l * std::floor((x[a] - lower[a]) / l);
        if (x[a] >= upper[a]) x[a] = lower[a];
      }
    return x;
  }
};

}  // namespace feedflow
