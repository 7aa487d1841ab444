#pragma once
// The tangent wave-speed bound for the explicit (CFL) time step (models.md 5.2):
// M_b = stiffness (linear + projection That:That) + |nonlinear| bounds the largest eigenvalue of
// the tangent acting on symmetric tensors (for G-B: f_s (a1^2 + That:That + f_d a1 |That + Ts|)),
// c_d = sqrt(M_b / rho), dt <= s L / (c_d + |v|).
#include "models/hypoplastic/stress_rate.hpp"

namespace feedflow {

// [Pa]
double tangent_modulus_bound(const RateTerms& terms);
double tangent_modulus_bound(const HypoplasticModel& m, const Tensor3& stress, double void_ratio);

// c_d = sqrt(M_b / rho) [m/s]; rho is the bulk density [kg/m^3] (> 0).
double dilatational_wave_speed_bound(const HypoplasticModel& m, const Tensor3& stress,
                                     double void_ratio, double bulk_density);

// dt = safety * L / (c_d + |v|) [s] for cell edge L [m]; safety > 0 (the Courant number: above 1
// the explicit update is unstable, which only the time-step stress tests ask for).
double cfl_time_step(double cell_size, double wave_speed, double speed, double safety);

}  // namespace feedflow
