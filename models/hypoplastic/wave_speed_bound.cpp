#include "models/hypoplastic/wave_speed_bound.hpp"

#include <cmath>
#include <stdexcept>

namespace feedflow {

double tangent_modulus_bound(const RateTerms& r) {
  // Near zero the rate k tr(D) I has the single non-zero eigenvalue 3k (on D = I/sqrt 3).
  if (r.near_zero) return 3.0 * r.near_zero_modulus;
  const double t_t = r.normalized_stress.cwiseAbs2().sum();
  return r.stiffness * (r.linear + r.projection * t_t) + r.nonlinear.norm();
}

double tangent_modulus_bound(const HypoplasticModel& m, const Tensor3& stress, double void_ratio) {
  return tangent_modulus_bound(rate_terms(m, stress, void_ratio));
}

double dilatational_wave_speed_bound(const HypoplasticModel& m, const Tensor3& stress,
                                     double void_ratio, double bulk_density) {
  if (!(bulk_density > 0.0))
    throw std::invalid_argument("dilatational_wave_speed_bound: bulk density must be > 0");
  return std::sqrt(tangent_modulus_bound(m, stress, void_ratio) / bulk_density);
}

double cfl_time_step(double cell_size, double wave_speed, double speed, double safety) {
  if (!(cell_size > 0.0) || !(wave_speed >= 0.0) || !(safety > 0.0 && std::isfinite(safety)))
    throw std::invalid_argument("cfl_time_step: need cell size > 0, wave speed >= 0 and a finite safety > 0");
  const double signal = wave_speed + std::abs(speed);
  if (!(signal > 0.0))
    throw std::invalid_argument("cfl_time_step: wave speed and material speed are both zero");
  return safety * cell_size / signal;
}

}  // namespace feedflow
