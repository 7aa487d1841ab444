#include "models/hypoplastic/material_point_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/hypoplastic/objective_rotation.hpp"
#include "models/hypoplastic/stress_rate.hpp"
#include "models/hypoplastic/stress_safeguards.hpp"
#include "models/hypoplastic/void_ratio_evolution.hpp"

namespace feedflow {

StepReport integrate_material_point(const HypoplasticModel& model, MaterialPointState& state,
                                    const Eigen::Matrix3d& stretching,
                                    const Eigen::Matrix3d& spin, double dt,
                                    const SubsteppingOptions& options) {
  if (!(dt > 0.0))
    throw std::invalid_argument("integrate_material_point: the time step must be > 0");
  StepReport report;
  const HypoplasticSafeguards& guard = model.safeguards;
  Tensor3& stress = state.stress;
  double& e = state.void_ratio;

  rotate_objectively(stress, spin, dt);
  apply_stress_safeguards(stress, guard);

  const double strain = tensor_norm(stretching) * dt;
  if (strain == 0.0) return report;  // the rate is homogeneous of degree 1 in D
  const Tensor3 increment = stretching * dt;  // strain increment of the whole step
  const double volumetric = increment.trace();
  const double h_min = 1.0 / options.max_substeps;
  const double h_max = std::min(1.0, options.max_substep_strain / strain);

  double done = 0.0;
  double h = h_max;
  while (done < 1.0) {
    h = std::min(h, 1.0 - done);
    const RateTerms terms = rate_terms(model, stress, e);
    const Tensor3 k1 = stress_rate(terms, increment);
    const Tensor3 euler = stress + h * k1;
    const double e_new = evolve_void_ratio(e, volumetric, h);
    const Tensor3 k2 = stress_rate(model, euler, e_new, increment);
    const Tensor3 heun = stress + (0.5 * h) * (k1 + k2);

    const double scale_new = std::max(heun.norm(), options.stress_scale);
    const double error = (0.5 * h) * (k2 - k1).norm() / scale_new;
    const double change = h * k1.norm() / std::max(stress.norm(), options.stress_scale);
    const bool within = error <= options.tolerance && change <= options.max_stress_change;
    const double error_ratio = error > 0.0 ? 0.9 * std::sqrt(options.tolerance / error) : 2.0;
    const double change_ratio = change > 0.0 ? 0.9 * options.max_stress_change / change : 2.0;

    if (within || h <= h_min) {
      if (!within) report.converged = false;
      stress = heun;
      e = guard.void_ratio_clamp ? clamp_void_ratio(e_new, model.parameters.e_d0,
                                                    model.parameters.e_i0, terms.bauer_factor)
                                 : e_new;
      apply_stress_safeguards(stress, guard);
      done += h;
      ++report.substeps;
      h = std::clamp(h * std::min(error_ratio, change_ratio), h_min, h_max);
      if (!within) h = h_min;
    } else {
      ++report.rejected;
      h = std::max(h * std::clamp(std::min(error_ratio, change_ratio), 0.1, 0.9), h_min);
    }
  }
  return report;
}

}  // namespace feedflow
