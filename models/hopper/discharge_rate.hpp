#pragma once
// Discharge rate of a hopper (reduced_models.md section 2). Rates are per metre of slot
// [kg/(s m)] for plane flow (wedge) and total [kg/s] for conical flow. Johanson with the
// cohesion factor (the default for mass flow), Beverloo (slot and circular), the hourglass
// upper bound and Carleton's air-drag correction. Brown-Richards: minimum_energy_discharge.hpp.
#include <limits>

#include "models/hopper/flow_function.hpp"
#include "models/hopper/hopper_geometry.hpp"

namespace feedflow {

struct JohansonDischarge {
  double rate;                // kg/(s m) plane, kg/s conical; 0 where the outlet arches
  double outlet_velocity;     // v0 [m/s]
  double cohesion_factor;     // 1 - ff/ff_a, in [0, 1]; 1 for a cohesionless solid
  double actual_flow_factor;  // ff_a = sigma1'/sigma_c(sigma1'); +infinity when sigma_c = 0
  double outlet_stress;       // sigma1' = ff rho_b g B / H(theta) [Pa]
  double bulk_density;        // rho_b(sigma1') [kg/m^3]
};

// Johanson (1965): v0 = sqrt(B g (1 - ff/ff_a) / (2 (1+m) tan theta)); W' = rho_b B v0 (plane),
// W = rho_b pi B^2/4 v0 (conical), rho_b taken at the outlet stress (a fixed point when the
// density depends on it).
JohansonDischarge johanson_discharge(FlowGeometry g, double semi_angle, double outlet_width,
                                     double flow_factor, const FlowFunction& ff_curve,
                                     const BulkDensity& density, double gravity = kGravity);

// Beverloo's empty annulus: the outlet acts k d narrower (k = 1.5); an outlet no wider than
// k d passes nothing.
inline constexpr double kBeverlooK = 1.5;

// Beverloo, circular outlet: W = C rho_b sqrt(g) (D - k d)^(5/2) [kg/s].
double beverloo_circular_rate(double bulk_density, double outlet_diameter, double particle_size,
                              double k = kBeverlooK, double c = 0.58, double gravity = kGravity);
// Beverloo, slot: W' = C2 rho_b sqrt(g) (B - k d)^(3/2) per metre [kg/(s m)] ...
double beverloo_slot_rate_per_metre(double bulk_density, double outlet_width,
                                    double particle_size, double k = kBeverlooK, double c2 = 1.03,
                                    double gravity = kGravity);
// ... and for a slot of length L: W = C2 rho_b sqrt(g) (L - k d)(B - k d)^(3/2) [kg/s].
double beverloo_slot_rate(double bulk_density, double outlet_width, double slot_length,
                          double particle_size, double k = kBeverlooK, double c2 = 1.03,
                          double gravity = kGravity);

// Rose & Tanaka (1956): a hopper steeper than its stagnant zone discharges faster than a flat
// bottom, Beverloo's rate times F = (tan theta tan phi_d)^-0.35 for theta < 90 deg - phi_d; a
// flatter one discharges as a flat bottom, F = 1. theta: semi-angle, phi_d: the stagnant-zone
// boundary's angle to the horizontal, both in (0, 90 deg).
double rose_tanaka_factor(double semi_angle, double stagnant_zone_angle);

// Hourglass theory (Savage; Davidson & Nedderman), an upper bound: stress ratio
// k = (1 + sin phi)/(1 - sin phi), sigma_r = 0 at the outlet arc and at the top radius r1.
// Plane needs k > 2 (phi > 19.5 deg), conical k > 1.5.
double hourglass_rate(FlowGeometry g, double bulk_density, double outlet_width,
                      double semi_angle, double internal_friction_angle,
                      double top_radius = std::numeric_limits<double>::infinity(),
                      double gravity = kGravity);

// Interstitial air opposing the flow of fine, light particles (Carleton 1972).
struct AirDrag {
  double particle_density;          // rho_p [kg/m^3] (envelope density for porous particles)
  double particle_size;             // d [m]
  double fluid_density = 1.2;       // rho_f [kg/m^3], air
  double fluid_viscosity = 1.8e-5;  // mu_f [Pa s], air
};
// Outlet velocity V0 solving 2(1+m) V0^2 sin theta / B
//   + 15 rho_f^(1/3) mu_f^(2/3) V0^(4/3) / (rho_p d^(5/3)) = g (GSL Brent) [m/s].
double carleton_outlet_velocity(FlowGeometry g, double semi_angle, double outlet_width,
                                const AirDrag& air, double gravity = kGravity);
// V0 with drag over V0 without (sqrt(g B / (2(1+m) sin theta))): the factor to apply to a rate.
double air_drag_factor(FlowGeometry g, double semi_angle, double outlet_width,
                       const AirDrag& air, double gravity = kGravity);

// A wedge's rate for its slot: the per-metre rate times the slot length [kg/s].
double slot_rate(double rate_per_metre, double slot_length);

}  // namespace feedflow
