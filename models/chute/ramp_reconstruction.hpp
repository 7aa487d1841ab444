#pragma once
// Second-order (MUSCL) reconstruction of the ramp state for the L1 chute scheme
// (ramp_flow_scheme.hpp). Per cell it gives the thickness and velocity on its two faces and the
// bed level there, as an offset from the exact linear bed z = -x tan(theta)/k of the slope.
//
// - Free surface eta = h + z and velocity u are reconstructed with van Leer's harmonic limiter;
//   the thickness follows as h = eta - z on the exact bed. On a ramp eta is monotone
//   wherever |h_x| < tan(theta)/k, so the limiter stays inactive at smooth extrema of h, the
//   bed offsets are zero and the centred slope source g sin(theta) h_i dx is exact: the slope
//   drive has no O(dx) deficit (the first-order hydrostatic reconstruction under-drives by
//   dx tan(theta)/(2 k h)).
// - Where that gives a negative face thickness (fronts, shorelines, thin layers) the cell falls
//   back to Audusse et al. (2004): h is reconstructed with minmod (h >= 0 on both faces) and the
//   bed inside the cell becomes z = eta - h. This keeps the lake at rest exact with dry cells.
// - Ghost cells: a Wall mirrors the cell (same h and bed, opposite u), so the surface of a pool
//   against it is flat; Outflow continues the ramp with the last thickness and no backward
//   velocity; Periodic wraps.
// The face thicknesses average to the cell thickness, (h_L + h_R)/2 = h_i, and lie in
// [0, max(h_i-1, h_i, h_i+1) + dx tan(theta)/(2k)].
#include <cstddef>
#include <vector>

#include "models/chute/ramp_problem.hpp"

namespace feedflow {

struct RampReconstruction {
  std::vector<double> h_left, h_right;  // thickness on the left/right face of each cell [m]
  std::vector<double> u_left, u_right;  // velocity there [m/s]
  std::vector<double> bed_right;        // bed offset on the right face; the left is -bed_right [m]
  std::size_t fallback_cells = 0;       // cells reconstructed by the Audusse fallback

  void resize(std::size_t n);
  // h and u are cell averages (u = 0 in dry cells); bed_step = z_(i+1) - z_i.
  void build(const RampPhysics& physics, double bed_step, const double* h, const double* u,
             std::size_t n);
};

}  // namespace feedflow
