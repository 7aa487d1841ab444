// The von Wolffersdorff (1996) rate law, for comparison (models.md 1.3). Same state variables,
// same safeguards, Matsuoka-Nakai-type F instead of the G-B a1(theta).
#include <algorithm>
#include <cmath>

#include "models/hypoplastic/stress_rate.hpp"
#include "models/hypoplastic/stress_terms.hpp"

namespace feedflow {

RateTerms von_wolffersdorff_terms(const HypoplasticModel& m, const Tensor3& stress, double e) {
  const HypoplasticParameters& hp = m.parameters;
  const HypoplasticConstants& c = m.constants;
  const double t = stress.trace();
  if (t > -m.safeguards.zero_stress_tolerance) return near_zero_terms(m, stress, e);

  const NormalizedStress s = normalized_stress(stress, t);
  const double tan_psi = std::sqrt(3.0 * s.j2);
  const double denominator =
      std::max(2.0 + std::sqrt(2.0) * tan_psi * s.cos3theta, 1e-12);  // > 0 inside the cone
  const double f = std::sqrt(std::max(
                       tan_psi * tan_psi / 8.0 + (2.0 - tan_psi * tan_psi) / denominator, 0.0)) -
                   tan_psi / (2.0 * std::sqrt(2.0));

  const PressureFactors pf = pressure_factors(hp, -t);
  const double e_i = hp.e_i0 * pf.bauer_factor;
  const double e_c = hp.e_c0 * pf.bauer_factor;
  const double e_d = hp.e_d0 * pf.bauer_factor;
  const double t_t = s.j2 + 1.0 / 3.0;  // That:That

  RateTerms r;
  r.bauer_factor = pf.bauer_factor;
  // f_b f_e: (e_i0/e_c0)^beta (e_c/e)^beta = (e_i/e)^beta.
  r.stiffness = hp.h_s / (hp.n * c.vw_denominator) * ((1.0 + e_i) / e_i) *
                density_power(e_i / e, hp.beta) * pf.pressure_power / t_t;
  r.density_factor = e > e_d ? density_power((e - e_d) / (e_c - e_d), hp.alpha) : 0.0;
  r.linear = f * f;
  r.projection = c.vw_a * c.vw_a;
  r.normalized_stress = s.that;
  r.nonlinear = (r.stiffness * r.density_factor * c.vw_a * f) * (s.that + s.deviator);
  return r;
}

}  // namespace feedflow
