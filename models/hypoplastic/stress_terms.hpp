#pragma once
// Pieces shared by the two rate laws: the normalised stress and its invariants, the pressure
// factors of the Bauer compression law, and the near-zero-stress branch (models.md 1.2, 1.5).
#include <algorithm>
#include <cmath>

#include "models/hypoplastic/stress_rate.hpp"

namespace feedflow {

struct NormalizedStress {
  Tensor3 that;      // T / tr T
  Tensor3 deviator;  // That - I/3
  double j2;         // Ts:Ts
  double cos3theta;  // -sqrt(6) J3 / J2^(3/2), clipped to [-1, 1]; 1 when J2 <= 1e-10
};

inline NormalizedStress normalized_stress(const Tensor3& stress, double trace) {
  NormalizedStress s;
  s.that = stress / trace;
  s.deviator = s.that;
  s.deviator.diagonal().array() -= 1.0 / 3.0;
  s.j2 = s.deviator.cwiseAbs2().sum();  // Ts:Ts >= 0 even for a slightly unsymmetric input
  const Tensor3 ts2 = s.deviator * s.deviator;
  if (s.j2 <= 1e-10) {
    s.cos3theta = 1.0;
  } else {
    const double j3 = ts2.cwiseProduct(s.deviator.transpose()).sum();
    s.cos3theta = std::clamp(-std::sqrt(6.0) * j3 / (s.j2 * std::sqrt(s.j2)), -1.0, 1.0);
  }
  return s;
}

struct PressureFactors {
  double bauer_factor;    // exp(-(-tr T/h_s)^n)
  double pressure_power;  // (-tr T/h_s)^(1-n)
};

inline PressureFactors pressure_factors(const HypoplasticParameters& hp, double minus_trace) {
  const double x = minus_trace / hp.h_s;
  const double xn = std::pow(x, hp.n);
  return {std::exp(-xn), x / xn};
}

// x^exponent with the common exponent 1 (beta of Table 1) done without pow.
inline double density_power(double x, double exponent) {
  return exponent == 1.0 ? x : std::pow(x, exponent);
}

inline RateTerms near_zero_terms(const HypoplasticModel& m, const Tensor3& stress, double e) {
  const HypoplasticParameters& hp = m.parameters;
  const double tol = m.safeguards.zero_stress_tolerance;
  RateTerms r;
  r.near_zero = true;
  r.bauer_factor = std::exp(-std::pow(std::max(-stress.trace(), 0.0) / hp.h_s, hp.n));
  // d(tr T)/dt of the compression law at 3p = tol: (de/dt)/(n e) tol/(tol/h_s)^n, shared equally
  // by the three normal components; de/dt = (1 + e) tr D.
  if (e <= hp.e_i0) r.near_zero_modulus = (1.0 + e) / (3.0 * hp.n * e) * tol / std::pow(tol / hp.h_s, hp.n);
  return r;
}

}  // namespace feedflow
