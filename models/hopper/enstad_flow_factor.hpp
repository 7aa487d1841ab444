#pragma once
// Closed-form flow factor of a converging hopper: Enstad's (1975) circular-arch slice with
// Jenike's arch, as in Arnold & McLean (1976), with the corrected [2(1 - cos)]^m term
// (reduced_models.md section 1.3). The designer's default flow factor. Also the passive
// (emptying) major-stress field sigma1(r) that the same slice balance gives.
#include <vector>

#include "models/hopper/hopper_geometry.hpp"

namespace feedflow {

// The slice-balance coefficients X and Y of section 1.3 (X > 1 in a converging hopper).
struct EnstadCoefficients {
  double x;
  double y;
};
EnstadCoefficients enstad_coefficients(FlowGeometry g, double semi_angle,
                                       double effective_friction_angle,
                                       double wall_friction_angle);

// ff = H(theta) (1 + sin delta) Y / [2 (X - 1) sin theta], with Jenike's H(theta).
// Throws std::invalid_argument for theta outside (0, 90 deg) or phi_w outside [0, delta].
double enstad_flow_factor(FlowGeometry g, double semi_angle, double effective_friction_angle,
                          double wall_friction_angle);

// Passive major principal stress sigma1 at distance r from the virtual apex, given its value
// sigma1_t at the transition r_t: sigma1(r) = rho g r (1+sin delta) Y/(X-1)
//   + [sigma1_t - rho g r_t (1+sin delta) Y/(X-1)] (r/r_t)^X.   [Pa]
struct PassiveStressPoint {
  double radius;        // distance from the virtual apex along the wall direction [m]
  double major_stress;  // sigma1 [Pa]
};
double enstad_passive_major_stress(FlowGeometry g, double semi_angle,
                                   double effective_friction_angle, double wall_friction_angle,
                                   double bulk_density, double transition_radius,
                                   double transition_major_stress, double radius,
                                   double gravity = kGravity);
// The same field at `points` radii evenly spaced from the outlet radius to the transition.
std::vector<PassiveStressPoint> enstad_passive_stress_profile(
    FlowGeometry g, double semi_angle, double effective_friction_angle,
    double wall_friction_angle, double bulk_density, double outlet_radius,
    double transition_radius, double transition_major_stress, int points = 50,
    double gravity = kGravity);

}  // namespace feedflow
