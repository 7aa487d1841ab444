#pragma once
// Homogeneous element tests on SUNDIALS CVODE (BDF, dense Newton): the state is the stress, the
// void ratio and the accumulated strain (integral of D); each loading stage prescribes, per
// component, the stretching or the stress rate (mixed_control.hpp) and may end early when a
// stress component reaches a value (CVODE root finding). This is the reference solution: the
// rate law alone, without the integrator's safeguards (reset, clamp).
#include <span>
#include <vector>

#include "models/hypoplastic/mixed_control.hpp"

namespace feedflow {

struct LoadingStage {
  ElementControl control;
  double duration = 0.0;  // [s]; the stage ends then at the latest
  // Optional early end: stress component stop_component (0..5) reaches stop_stress [Pa].
  int stop_component = -1;
  double stop_stress = 0.0;
  int samples = 50;  // output points in the stage (equally spaced in time)
};

struct ElementTestSample {
  double time = 0.0;                                 // [s]
  int stage = 0;
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();  // [Pa], tension positive
  double void_ratio = 0.0;                           // [-]
  Eigen::Matrix3d strain = Eigen::Matrix3d::Zero();  // integral of D [-]
};

struct ElementTestTolerances {
  double relative = 1e-8;
  double stress_absolute = 1e-6;      // [Pa]
  double void_ratio_absolute = 1e-12;
  double strain_absolute = 1e-12;
  long max_steps = 200000;            // per stage
};

// The path, starting with the initial state (time 0, stage 0). Throws NumericalFailure when
// CVODE or the mixed-control solve fails, std::invalid_argument for a malformed stage.
std::vector<ElementTestSample> run_element_test(const HypoplasticModel& model,
                                                const MaterialPointState& initial,
                                                std::span<const LoadingStage> stages,
                                                const ElementTestTolerances& tolerances = {});

}  // namespace feedflow
