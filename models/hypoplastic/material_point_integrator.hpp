#pragma once
// The routine the CEL solver calls for every cell at every step: the objective rotation of the
// old stress, then T and e over the step with the same D, by modified Euler (Heun) substeps with
// a Sloan-type local error control (models.md 1.6). Allocation-free; fixed-size Eigen only.
#include <Eigen/Core>

#include "models/hypoplastic/hypoplastic_model.hpp"

namespace feedflow {

struct MaterialPointState {
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();  // Cauchy stress, tension positive [Pa]
  double void_ratio = 0.0;                           // [-]
};

struct SubsteppingOptions {
  // Accept a substep when ||T_heun - T_euler|| <= tolerance * max(||T_new||, stress_scale).
  double tolerance = 1e-3;
  double stress_scale = 1e-3;         // [Pa], absolute floor of the error norm
  double max_substep_strain = 1e-4;   // ||D|| dt of one substep at most
  double max_stress_change = 0.1;     // ||dT|| of one substep over max(||T||, stress_scale)
  int max_substeps = 4096;            // smallest substep = step / max_substeps (then forced)
};

struct StepReport {
  int substeps = 0;        // accepted
  int rejected = 0;
  bool converged = true;   // false: a substep at the smallest size was forced past the tolerance
};

// Advances `state` by dt under stretching D and spin W (both [1/s], D symmetric, W skew).
// dt <= 0 is an invalid argument. The safeguards of the model apply (input and substep tension
// reset, pressure cutoff, void-ratio clamp at the stress before each substep).
StepReport integrate_material_point(const HypoplasticModel& model, MaterialPointState& state,
                                    const Eigen::Matrix3d& stretching,
                                    const Eigen::Matrix3d& spin, double dt,
                                    const SubsteppingOptions& options = {});

}  // namespace feedflow
