#pragma once
// The semi-discrete finite-volume scheme of the L1 chute model: 1-D Savage-Hutter type depth-
// averaged flow along an inclined ramp, in slope-aligned coordinates (x along the ramp, h normal
// to it, u depth averaged):
//   h_t + (h u)_x = 0,
//   (h u)_t + (h u^2 + k g cos(theta) h^2/2)_x = g h sin(theta) - mu(h, Fr) g cos(theta) h sgn(u),
// with k the earth-pressure coefficient and mu the Pouliquen/Forterre depth-averaged law
// (pouliquen_law.hpp). Gravity along the slope is written as a bed z = -x tan(theta)/k.
//
// Second order in space: MUSCL reconstruction of the free surface h + z and of u
// (ramp_reconstruction.hpp), Rusanov flux on the hydrostatically reconstructed states of
// Audusse et al. (2004) (z* = max(z_L, z_R), h* = max(0, h + z - z*)) and their well-balanced
// source: the face corrections p(h) - p(h*) plus the centred bed source
// k g cos(theta) (h_L + h_R)/2 (z_L - z_R) of each cell. On the exact bed that centred source is
// g sin(theta) h_i dx, consistent to any order. Properties:
// - a lake at rest (flat free surface, dry cells included) is exact;
// - positivity: every face thickness is >= 0 and they average to h_i, so a forward Euler step
//   keeps h >= 0 for a dt/dx <= 1/2 with a the largest face wave speed (max_wave_speed bounds
//   it), hence any SSP Runge-Kutta method such as Heun;
// - mass is conserved to round-off; what leaves through an Outflow end is bookkept.
//
// Friction (the Coulomb threshold) is split so that a layer inside the Coulomb cone stays
// EXACTLY at rest and a moving one is stopped in finite time:
// - momentum: the fluxes and sources above carry no friction; after every Runge-Kutta stage an
//   implicit stopping step (apply_friction, implicit_friction.hpp) reduces |q| by
//   dt mu(h, Fr) g cos(theta) h with mu at the NEW speed (backward Euler, so a uniform layer
//   reaches the flow rule at any dt), and sets it to exactly zero when dt mu_stop(h) g cos h
//   exceeds it. At the end of the step (end_step) a cell moving at its start gets the
//   trapezoidal friction (half the start friction explicitly, the stopping step over dt/2 for
//   the other half): with the backward-Euler predictor stage this is second order in time. A
//   cell at rest at the start gets the stopping step over dt: inside the cone the explicit
//   update is smaller than that impulse on every stage, so q stays exactly 0;
// - mass: between two cells at rest (q = 0 at the start of the step) the mass flux uses the cell
//   averages with the friction at rest added as an apparent bed step |dz_f| <= mu_stop(h) dx/k
//   that balances as much of the surface step as it can (Bouchut's "friction as topography").
//   A resting layer inside the cone then has equal reconstructed thicknesses and no mass flux
//   (no creep by the Rusanov diffusion). The thickness stays positive (h* <= h).
#include <cstddef>
#include <vector>

#include "models/chute/implicit_friction.hpp"
#include "models/chute/ramp_problem.hpp"
#include "models/chute/ramp_reconstruction.hpp"

namespace feedflow {

// State layout: h[0..n), q[0..n) with q = h u, then the volume per unit width that has left
// through Outflow ends (so that sum(h) dx + outflow is conserved to round-off).
class RampFlowScheme {
 public:
  RampFlowScheme(RampGrid grid, RampPhysics physics);  // throws std::invalid_argument

  std::size_t state_size() const { return 2 * grid_.cells + 1; }
  const RampGrid& grid() const { return grid_; }
  const RampPhysics& physics() const { return physics_; }

  // Records which cells are at rest (q == 0) at the start of a step and the friction on the
  // moving ones.
  void begin_step(const double* state);
  // dy/dt without friction; returns false (and records where) on a non-finite value.
  bool rhs(const double* state, double* derivative);
  // The implicit Coulomb stopping step over a time dt (backward Euler; the stages).
  void apply_friction(double* state, double dt) const;
  // The friction of a whole step of length dt on the frictionless update: trapezoidal on cells
  // that were moving at its start (second order in time), the stopping step over dt on cells
  // that were at rest (so that the Coulomb threshold is exact).
  void end_step(double* state, double dt) const;
  // Bound on the face wave speeds |u| + sqrt(k g cos h) of the reconstruction [m/s].
  double max_wave_speed(const double* state) const;
  double velocity(double h, double q) const;
  std::size_t failed_cell() const { return failed_cell_; }

 private:
  struct Star {
    double left, right;  // reconstructed thicknesses on both sides of a face
  };
  // First-order states of a pair of resting cells with the friction at rest as topography.
  Star resting_pair(std::size_t face, double hl, double hr) const;
  void cap_at_gate(std::size_t face, Star& s) const;
  double pressure(double h) const { return 0.5 * gk_ * h * h; }

  RampGrid grid_;
  RampPhysics physics_;
  ImplicitFriction friction_;
  double gk_;       // k g cos(theta)
  double dz_;       // bed step per cell, -dx tan(theta)/k
  std::vector<char> rest_;  // cells at rest at the start of the step
  std::vector<double> friction_start_;  // mu g cos(theta) h sgn(q) at the start [m^2/s^2]
  std::vector<double> u_;   // cell velocities of the current evaluation
  RampReconstruction rec_;
  std::size_t failed_cell_ = 0;
};

}  // namespace feedflow
