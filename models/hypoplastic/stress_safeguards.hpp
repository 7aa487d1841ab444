#pragma once
// The stress safeguards of models.md 1.5/1.6: the INL per-component tension reset and the
// optional smooth isotropic pressure cutoff.
#include <Eigen/Core>

#include "models/hypoplastic/hypoplastic_model.hpp"

namespace feedflow {

// Every normal component >= 0 becomes -reset_stress; components in (-reset_stress, 0) and the
// shear components are left as they are (INL VUMAT behaviour).
inline void reset_tensile_components(Eigen::Matrix3d& stress, double reset_stress) {
  for (int k = 0; k < 3; ++k)
    if (stress(k, k) >= 0.0) stress(k, k) = -reset_stress;
}

// Shifts the stress isotropically so that p = -tr T/3 >= minimum_pressure.
inline void apply_pressure_cutoff(Eigen::Matrix3d& stress, double minimum_pressure) {
  const double shortfall = stress.trace() + 3.0 * minimum_pressure;
  if (shortfall > 0.0) stress.diagonal().array() -= shortfall / 3.0;
}

inline void apply_stress_safeguards(Eigen::Matrix3d& stress, const HypoplasticSafeguards& s) {
  if (s.minimum_pressure > 0.0) apply_pressure_cutoff(stress, s.minimum_pressure);
  if (s.tension_reset) reset_tensile_components(stress, s.tension_reset_stress);
}

}  // namespace feedflow
