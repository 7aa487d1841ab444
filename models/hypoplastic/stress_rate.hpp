#pragma once
// The hypoplastic objective stress rate T°(T, e, D) on full 3x3 tensors (tension positive,
// models.md 1.1-1.3). The state-dependent part is computed once as RateTerms; the rate is then
// linear in D plus a term in ||D||:
//   T° = stiffness [ linear D + projection (That:D) That ] + nonlinear ||D||
// which is what the stress integrator, the mixed-control element tests (their Jacobian) and the
// wave-speed bound all need.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "models/hypoplastic/hypoplastic_model.hpp"

namespace feedflow {

using Tensor3 = Eigen::Matrix3d;

struct RateTerms {
  double stiffness = 0.0;   // f_s (G-B) or f_b f_e/(That:That) (von Wolffersdorff) [Pa]
  double linear = 0.0;      // a1^2 (G-B) or F^2 (vW) [-]
  double projection = 0.0;  // 1 (G-B) or a^2 (vW) [-]
  Tensor3 normalized_stress = Tensor3::Zero();  // That = T / tr T
  Tensor3 nonlinear = Tensor3::Zero();          // stiffness f_d N [Pa]
  double density_factor = 0.0;                  // f_d [-]
  double bauer_factor = 1.0;  // exp(-(3p/h_s)^n): e_x(p) = e_x0 * bauer_factor
  // Near-zero or tensile stress (|tr T| < tolerance or tr T > 0): the rate is isotropic,
  // T°_kk = near_zero_modulus * min(tr D, 0) (models.md 1.5 item 6).
  bool near_zero = false;
  double near_zero_modulus = 0.0;  // [Pa]
};

// ||D|| = sqrt(D:D), tensor components (each shear component counted twice).
inline double tensor_norm(const Tensor3& d) { return std::sqrt(d.cwiseAbs2().sum()); }

RateTerms gudehus_bauer_terms(const HypoplasticModel& m, const Tensor3& stress, double void_ratio);
RateTerms von_wolffersdorff_terms(const HypoplasticModel& m, const Tensor3& stress,
                                  double void_ratio);

inline RateTerms rate_terms(const HypoplasticModel& m, const Tensor3& stress, double void_ratio) {
  return m.variant == HypoplasticVariant::gudehus_bauer
             ? gudehus_bauer_terms(m, stress, void_ratio)
             : von_wolffersdorff_terms(m, stress, void_ratio);
}

inline Tensor3 stress_rate(const RateTerms& r, const Tensor3& stretching) {
  if (r.near_zero)
    return Tensor3::Identity() * (r.near_zero_modulus * std::min(stretching.trace(), 0.0));
  const double t_d = r.normalized_stress.cwiseProduct(stretching).sum();
  return r.stiffness * (r.linear * stretching + (r.projection * t_d) * r.normalized_stress) +
         tensor_norm(stretching) * r.nonlinear;
}

// T°(T, e, D) [Pa/s] for stretching D [1/s].
inline Tensor3 stress_rate(const HypoplasticModel& m, const Tensor3& stress, double void_ratio,
                           const Tensor3& stretching) {
  return stress_rate(rate_terms(m, stress, void_ratio), stretching);
}

}  // namespace feedflow
