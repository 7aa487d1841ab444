#pragma once
// The implicit (backward Euler) Coulomb stopping step of the L1 chute model for the Pouliquen/
// Forterre basal friction (pouliquen_law.hpp): given the speed u* a cell would have without
// friction after a time dt, the new speed u >= 0 solves
//   u + dt g cos(theta) mu(h, u/sqrt(g h)) = u*,
// with mu evaluated at the NEW speed, or u = 0 when u* <= dt g cos(theta) mu(h, 0) (the layer is
// held inside the Coulomb cone). mu grows with the speed, so the root is unique; on the dynamic
// branch the equation is a quadratic in Fr. Evaluating mu at u* instead (an explicit friction
// coefficient) overshoots on coarse steps: once dt g sin(theta) exceeds the steady speed, mu(u*)
// exceeds tan(theta) and the step stops a layer that should flow at the flow rule. With the new
// speed in mu, a steady uniform layer satisfies mu = tan(theta), the flow rule, at any dt.
#include "models/chute/pouliquen_law.hpp"

namespace feedflow {

// The basal law with its tangents computed once (the scheme calls it per cell and stage).
class ImplicitFriction {
 public:
  explicit ImplicitFriction(const PouliquenLaw& law);
  // mu_stop(h), as basal_friction_at_rest.
  double at_rest(double thickness) const;
  // mu(h, Fr), as basal_friction.
  double coefficient(double thickness, double froude) const;
  // thickness h > 0 [m], explicit_speed u* >= 0 [m/s], impulse_per_mu = dt g cos(theta) [m/s]:
  // the speed after the stopping step [m/s].
  double speed_after(double thickness, double explicit_speed, double impulse_per_mu) const;

 private:
  PouliquenLaw law_;
  double tan1_, span_;  // tan(theta1), tan(theta2) - tan(theta1)
};

}  // namespace feedflow
