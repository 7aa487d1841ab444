#pragma once
// Dynamic angle of repose of a rolling drum from a mu(I) flowing layer (reduced_models.md
// section 4, steps 1-5, [DER, semi-empirical]):
//   q = omega L_c^2/2 (solid-body supply through mid-chord), delta_L = c_delta L_c,
//   I = (5/2) q d/(sqrt(phi g cos beta) delta_L^(5/2))  (Bagnold layer carrying q),
//   tan beta = mu(I) + mu_ew delta_L/W                   (end-wall friction, Jop et al. 2005).
// The fixed point in beta is found as a GSL Brent root, bracketed by atan(mu_s) and
// atan(mu_2 + mu_ew delta_L/W).
#include "models/chute/mu_i_rheology.hpp"
#include "models/equipment/drum.hpp"

namespace feedflow {

struct RollingLayerModel {
  MuIRheology rheology;              // mu_s, mu_2, I0, d, phi of the material
  double layer_fraction = 0.2;       // c_delta = delta_L/L_c, fitted (0.1-0.3)
  double end_wall_friction = 0.0;    // mu_ew, material on the end walls [-]
};

struct RollingLayerState {
  double angle_of_repose;   // beta [rad], the mid-chord slope
  double inertial_number;   // I of the flowing layer
  double layer_thickness;   // delta_L [m]
  double flux;              // q [m^2/s] per metre of drum length
};

// Throws std::invalid_argument for a bad drum or model; NumericalFailure if Brent fails.
// Valid in the rolling regime only: the caller checks the regime (drum_regime.hpp).
RollingLayerState rolling_angle_of_repose(const Drum& drum, const RollingLayerModel& model);

}  // namespace feedflow
