#pragma once
// Brown & Richards' minimum-energy discharge of a wedge hopper (reduced_models.md section 2,
// item 3): the flow crosses the arc r0 = B/(2 sin theta) about the apex with
// u(phi) = sqrt(2 g r0 (e - cos phi)), where e solves
//   integral_0^theta (2e - 3 cos phi)/sqrt(e - cos phi) dphi = 0     (GSL Brent + QAGS),
// and W' = rho_b sqrt(g) r0^(3/2) 2 integral_0^theta sqrt(2(e - cos phi)) dphi.

namespace feedflow {

struct MinimumEnergyDischarge {
  double coefficient;      // W' / (rho_b sqrt(g) B^(3/2))
  double energy_constant;  // e
};

// Semi-angle in (0, 90 deg]; 90 deg is the flat-bottomed slot (use it beyond the stagnant-zone
// angle). Throws NumericalFailure if the quadrature or the root finding fails.
MinimumEnergyDischarge brown_richards_wedge(double semi_angle);

// W' [kg/(s m)] = coefficient rho_b sqrt(g) B^(3/2).
double brown_richards_rate_per_metre(double bulk_density, double outlet_width,
                                     double semi_angle, double gravity = 9.81);

}  // namespace feedflow
