#pragma once
// The semi-discrete finite-volume scheme of the L1 chute model: 1-D Savage-Hutter type depth-
// averaged flow along an inclined ramp, in slope-aligned coordinates (x along the ramp, h normal
// to it, u depth averaged):
//   h_t + (h u)_x = 0,
//   (h u)_t + (h u^2 + k g cos(theta) h^2/2)_x = g h sin(theta) - mu(h, Fr) g cos(theta) h sgn(u),
// with k the earth-pressure coefficient and mu the Pouliquen/Forterre depth-averaged law
// (pouliquen_law.hpp). First-order finite volumes, Rusanov flux, and the hydrostatic
// reconstruction of Audusse et al. (2004) with the gravity written as a bed z = -x tan(theta)/k,
// so that the scheme is well balanced (a lake at rest is exact) and positivity preserving under
// CFL a dt/dx <= 1/2 (forward Euler, hence any SSP Runge-Kutta such as Heun).
//
// Friction (the Coulomb threshold) is split so that a layer inside the Coulomb cone stays
// EXACTLY at rest and a moving one is stopped in finite time:
// - momentum: gravity-only hydrostatic reconstruction (lake at rest exact), then after each
//   Runge-Kutta step an implicit stopping step on every cell (apply_friction): |q| is reduced by
//   dt mu(h, Fr) g cos(theta) h and set to exactly zero when the impulse exceeds it. Inside the
//   cone the explicit update is smaller than the impulse, so q stays exactly 0;
// - mass: between two cells at rest (q = 0 at the start of the step, for all its stages) the
//   reconstruction adds the friction at rest as
//   an apparent bed step
//   |dz_f| <= mu_stop(h) dx/k that balances as much of the surface step as it can (Bouchut's
//   "friction as topography"). Without it the Rusanov diffusion a (h*_R - h*_L)/2 moves mass
//   downslope between cells at rest (h*_R - h*_L = dx tan(theta)/k) and a deposit creeps away
//   at O(dx) speed; with it, a layer inside the cone has equal reconstructed thicknesses and no
//   mass flux. The thickness stays positive (h* <= h in every reconstruction).
#include <cstddef>
#include <optional>
#include <vector>

#include "models/chute/pouliquen_law.hpp"

namespace feedflow {

enum class RampBoundary {
  Wall,      // closed end: no mass flux, pressure reaction
  Outflow,   // free lower end: a ghost continues the ramp; material leaves, never enters
             // (downstream only)
  Periodic,  // the two ends joined (uniform-flow tests)
};

struct RampGrid {
  double x_begin = 0.0;  // upstream end [m]
  double x_end = 0.0;    // downstream end [m]
  std::size_t cells = 0;
  double dx() const { return (x_end - x_begin) / static_cast<double>(cells); }
  double centre(std::size_t i) const { return x_begin + (static_cast<double>(i) + 0.5) * dx(); }
};

struct RampPhysics {
  double angle = 0.0;           // ramp inclination [rad]
  PouliquenLaw friction;        // basal law; theta1 == theta2 is a Coulomb law, 0 == 0 none
  double earth_pressure = 1.0;  // k [-]
  RampBoundary upstream = RampBoundary::Wall;
  RampBoundary downstream = RampBoundary::Outflow;
  std::optional<std::size_t> gate_face;  // face index (0..cells) carrying a gate
  double gate_opening = 0.0;             // clear height under the gate [m]
  double dry_thickness = 1e-10;          // thinner cells have no velocity [m]
};

// State layout: h[0..n), q[0..n) with q = h u, then the volume per unit width that has left
// through Outflow ends (so that sum(h) dx + outflow is conserved to round-off).
class RampFlowScheme {
 public:
  RampFlowScheme(RampGrid grid, RampPhysics physics);  // throws std::invalid_argument

  std::size_t state_size() const { return 2 * grid_.cells + 1; }
  const RampGrid& grid() const { return grid_; }
  const RampPhysics& physics() const { return physics_; }

  // Records which cells are at rest (q == 0) at the start of a step.
  void begin_step(const double* state);
  // dy/dt; returns false (and records where) on a non-finite value.
  bool rhs(const double* state, double* derivative);
  // The implicit Coulomb stopping step after a Runge-Kutta step of length dt.
  void apply_friction(double* state, double dt) const;
  // Largest wave speed |u| + sqrt(k g cos h) over the cells [m/s].
  double max_wave_speed(const double* state) const;
  double velocity(double h, double q) const;
  std::size_t failed_cell() const { return failed_cell_; }

 private:
  struct Star {
    double left, right;  // reconstructed thicknesses on both sides of a face
  };
  Star reconstruct(std::size_t face, double hl, double hr, bool with_friction) const;
  double pressure(double h) const { return 0.5 * gk_ * h * h; }

  RampGrid grid_;
  RampPhysics physics_;
  double gk_;       // k g cos(theta)
  double dz_;       // bed step per cell, -dx tan(theta)/k
  std::vector<char> rest_;  // cells at rest at the start of the step
  std::size_t failed_cell_ = 0;
};

}  // namespace feedflow
