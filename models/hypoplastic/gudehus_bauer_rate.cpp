// The Gudehus-Bauer rate law exactly as the seed authors' VUMAT evaluates it (models.md 1.2).
#include <algorithm>
#include <cmath>

#include "models/hypoplastic/stress_rate.hpp"
#include "models/hypoplastic/stress_terms.hpp"

namespace feedflow {

RateTerms gudehus_bauer_terms(const HypoplasticModel& m, const Tensor3& stress, double e) {
  const HypoplasticParameters& hp = m.parameters;
  const HypoplasticConstants& c = m.constants;
  const double t = stress.trace();
  if (t > -m.safeguards.zero_stress_tolerance) return near_zero_terms(m, stress, e);

  const NormalizedStress s = normalized_stress(stress, t);
  const double a1 = 1.0 / (c.c1 + c.c2 * std::sqrt(s.j2) * (1.0 + s.cos3theta));

  const PressureFactors pf = pressure_factors(hp, -t);
  const double e_i = hp.e_i0 * pf.bauer_factor;
  const double e_c = hp.e_c0 * pf.bauer_factor;
  const double e_d = hp.e_d0 * pf.bauer_factor;

  RateTerms r;
  r.bauer_factor = pf.bauer_factor;
  r.stiffness = hp.h_s / (hp.n * c.h_i) * ((1.0 + e_i) / e_i) * density_power(e_i / e, hp.beta) *
                pf.pressure_power;
  r.density_factor = e > e_d ? density_power((e - e_d) / (e_c - e_d), hp.alpha) : 0.0;
  r.linear = a1 * a1;
  r.projection = 1.0;
  r.normalized_stress = s.that;
  r.nonlinear = (r.stiffness * r.density_factor * a1) * (s.that + s.deviator);
  return r;
}

}  // namespace feedflow
