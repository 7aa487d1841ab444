#pragma once
// Vertical and wall stresses down a converging hopper by the slice method (Walker / Motzkus /
// Schulze, reduced_models.md section 5). h is the height above the virtual apex:
//   d sigma_v/dh = n sigma_v / h - rho_b g,   n = (m+1)[lambda_h (1 + tan phi_w / tan theta) - 1]
//   sigma_v(h) = rho_b g h/(n-1) [1 - (h/h_t)^(n-1)] + sigma_vt (h/h_t)^n      (n != 1)
// with sigma_n = lambda_h sigma_v and tau_w = tan(phi_w) sigma_n. Also the whole silo: Janssen
// in the bin, then the slice from the transition down to the outlet.
#include <vector>

#include "models/equipment/hopper.hpp"
#include "models/hopper/bin_stresses.hpp"
#include "models/hopper/hopper_geometry.hpp"

namespace feedflow {

// Emptying (passive) wall-to-vertical stress ratio
// lambda_h = (1 + sin delta cos 2beta)/(1 - sin delta cos 2(beta + theta)).
double passive_hopper_stress_ratio(double semi_angle, double effective_friction_angle,
                                   double wall_friction_angle);

struct HopperSlice {
  FlowGeometry geometry;
  double semi_angle;           // [rad]
  double wall_friction_angle;  // [rad]
  double stress_ratio;         // lambda_h (passive_hopper_stress_ratio when emptying)
  double bulk_density;         // [kg/m^3]
  double transition_height;    // h_t above the virtual apex [m]
  double transition_stress;    // sigma_vt, e.g. Janssen's at the bottom of the bin [Pa]
  double gravity = kGravity;
};

struct HopperStressPoint {
  double height;       // above the virtual apex [m]
  double vertical;     // mean vertical stress sigma_v [Pa]
  double wall_normal;  // [Pa]
  double wall_shear;   // [Pa]
};

double slice_exponent(const HopperSlice& slice);
HopperStressPoint slice_stress(const HopperSlice& slice, double height);
// `points` heights evenly spaced from the transition down to `outlet_height`.
std::vector<HopperStressPoint> hopper_slice_profile(const HopperSlice& slice,
                                                    double outlet_height, int points = 50);

// The silo while emptying, top to outlet, heights above the virtual apex: Janssen in the bin
// (lambda by `rule` with the effective angle delta, plane bin of the hopper's bin width and
// slot length, or round), then the passive slice below the transition. The wall normal stress
// jumps at the transition (the "switch" stress).
std::vector<HopperStressPoint> emptying_silo_profile(const Hopper& hopper, double bulk_density,
                                                     double effective_friction_angle,
                                                     double wall_friction_angle,
                                                     StressRatioRule rule, int points = 50,
                                                     double gravity = kGravity);

}  // namespace feedflow
