#pragma once
// Damping coefficients from the coefficient of restitution e (models.md 4.3).
namespace feedflow {

// beta_e = ln e / sqrt(ln^2 e + pi^2) (negative; 0 for e = 1, -1 for e = 0).
double restitution_beta(double restitution);

// ln^2 e / (ln^2 e + pi^2) = 1/(1 + (pi/ln e)^2): a linear spring k with dashpot
// sqrt(4 m* k * factor) rebounds with exactly e (the form inside the hysteretic laws).
double linear_damping_factor(double restitution);

// How the Hertz dashpot gamma = c sqrt(S m*) (S = 2 E* sqrt(R* delta)) is scaled.
enum class HertzDampingForm {
  restitution_exact,  // c solved so that a Hertz impact (force clipped at zero) rebounds with e
  liggghts,           // c = -2 sqrt(5/6) beta_e, as LIGGGHTS `hertz` (e = 0.3 rebounds with 0.397)
};

// The coefficient c of gamma_n = c sqrt(S_n m*). The exact form integrates the dimensionless
// damped Hertz impact (the rebound does not depend on speed, radius, mass or modulus) and
// inverts it by bisection; about a millisecond, done once per law.
double hertz_damping_coefficient(double restitution, HertzDampingForm form);

// Restitution of one dimensionless Hertz impact with coefficient c (force clipped at zero).
double hertz_restitution(double coefficient);

}  // namespace feedflow
