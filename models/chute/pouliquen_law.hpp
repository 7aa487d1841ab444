#pragma once
// Pouliquen's stopping-thickness law and flow rule for a granular layer on a rough incline
// (reduced_models.md section 3 items 1-2): h_stop(theta), the flow rule Fr = beta h/h_stop - Gamma
// with Fr = u/sqrt(g h), chute sizing h(q), and the depth-averaged basal friction mu(h, Fr) of
// Pouliquen & Forterre (2002) that the L1 chute model uses. Thicknesses are normal to the plane.
#include <optional>
#include <string>
#include <string_view>

#include "models/core/gravity.hpp"

namespace feedflow {


// Forterre & Pouliquen (2003) form: h_stop = L (tan theta2 - tan theta)/(tan theta - tan theta1).
struct PouliquenLaw {
  double theta1 = 0.0;  // angle below which every layer is static [rad]
  double theta2 = 0.0;  // angle above which no layer stops [rad]
  double length = 0.0;  // L [m]
  double beta = 0.136;  // beta_P of the flow rule [-] (glass beads)
  double gamma = 0.0;   // Gamma of the flow rule [-]
};

// Pouliquen (1999) form: tan theta_stop(h) = tan theta1 + (tan theta2 - tan theta1) exp(-h/(A d)).
struct PouliquenExponentialLaw {
  double theta1 = 0.0;  // [rad]
  double theta2 = 0.0;  // [rad]
  double decay_length = 0.0;  // A d [m]
};

enum class DepositOutcome {
  Deposit,             // a finite h_stop
  NoDepositAboveTheta2,  // theta >= theta2: every layer flows off, nothing stops
  NeverFlowsBelowTheta1  // theta <= theta1: every layer is static, h_stop is infinite
};
// The label of the `deposit` estimate: "a layer stays behind", "no deposit (above theta2)",
// "never flows (below theta1)"; and back (empty for any other text).
const char* to_string(DepositOutcome o);
std::optional<DepositOutcome> deposit_outcome_from_string(std::string_view text);

struct StoppingThickness {
  DepositOutcome outcome = DepositOutcome::Deposit;
  double thickness = 0.0;  // [m]; 0 above theta2, +infinity below theta1
  std::string words;       // the outcome said for a person
};

// Throws std::invalid_argument unless 0 <= theta1 < theta2 < pi/2 and length > 0 (beta > 0,
// gamma >= 0 for the flow-rule functions).
void check(const PouliquenLaw& law);
StoppingThickness stopping_thickness(const PouliquenLaw& law, double angle);
StoppingThickness stopping_thickness(const PouliquenExponentialLaw& law, double angle);

// Flow rule: Froude number u/sqrt(g h) of a steady uniform layer of thickness h at `angle`.
// Returns 0 for a layer too thin to flow (beta h/h_stop <= Gamma).
// Throws std::invalid_argument outside theta1 < angle < theta2 (no finite h_stop there).
double flow_rule_froude(const PouliquenLaw& law, double thickness, double angle);
double flow_rule_velocity(const PouliquenLaw& law, double thickness, double angle);  // [m/s]

// Chute sizing: the steady uniform thickness carrying q = Q/width [m^2/s] at `angle`. With
// Gamma = 0 the closed form h = [q h_stop/(beta sqrt g)]^(2/5); otherwise a GSL Brent root of
// q = h u(h). Angles at or above theta2 have no h_stop and are refused (std::invalid_argument).
double thickness_for_flow_rate(const PouliquenLaw& law, double flow_rate_per_width,
                               double angle);

// Depth-averaged basal friction coefficient (Pouliquen & Forterre 2002, without hysteresis):
//   mu_stop(h) = tan theta1 + (tan theta2 - tan theta1)/(h/L + 1)           for Fr < beta - Gamma
//   mu_dyn(h, Fr) = tan theta1 + (tan theta2 - tan theta1)/(beta h/(L (Fr + Gamma)) + 1) otherwise.
// Continuous at Fr = beta - Gamma; tan(angle) = mu_dyn is exactly the flow rule; tan(angle) =
// mu_stop(h) is exactly h = h_stop(angle). With Gamma = 0 it equals mu(I) of the depth-averaged
// inertial number I = (5/2) d u/(h sqrt(g h)) with I0 = 5 beta d/(2 L) (see mu_i_rheology.hpp).
// Here theta1 == theta2 is allowed (a Coulomb friction tan theta1); theta1 = theta2 = 0 is
// frictionless.
double basal_friction_at_rest(const PouliquenLaw& law, double thickness);
double basal_friction(const PouliquenLaw& law, double thickness, double froude);

}  // namespace feedflow
