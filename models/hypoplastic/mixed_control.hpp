#pragma once
// Mixed stress/strain control of a homogeneous element: each of the six tensor components
// (xx, yy, zz, xy, yz, zx) has either its stretching D_ij or its stress rate dT_ij/dt prescribed;
// the unknown stretching components are solved from the rate law
//   dT/dt = T°(T, e, D) + W T - T W   (Jaumann, models.md 1.1).
// T° = L:D + N ||D|| is linear in D for a given s = ||D||, so the unknowns are affine in s,
// D = a + b s, and s = ||a + b s|| is a quadratic: the solve is exact (Eigen LU for the linear
// part), without iteration and without jumping between roots. Two admissible roots (|b| > 1,
// loss of uniqueness) take the smaller s; none throws NumericalFailure.
#include <array>

#include <Eigen/Core>

#include "models/hypoplastic/material_point_integrator.hpp"

namespace feedflow {

enum class ComponentControl { strain, stress };

// Component k of the six: row/column of the tensor.
inline constexpr std::array<int, 6> kComponentRow{0, 1, 2, 0, 1, 2};
inline constexpr std::array<int, 6> kComponentColumn{0, 1, 2, 1, 2, 0};

struct ElementControl {
  std::array<ComponentControl, 6> control{};  // strain by default
  std::array<double, 6> rate{};  // D_ij [1/s] (strain control) or dT_ij/dt [Pa/s] (stress)
  Eigen::Matrix3d spin = Eigen::Matrix3d::Zero();  // W [1/s]
};

struct ElementRates {
  Eigen::Matrix3d stretching;   // D [1/s]
  Eigen::Matrix3d stress_rate;  // dT/dt including the spin terms [Pa/s]
};

// Solves for the unknown stretching components of one control. Throws NumericalFailure when no
// stretching satisfies the control (e.g. stress control at zero stress).
class MixedControlSolver {
 public:
  // Throws std::invalid_argument when all six components are stress-controlled.
  MixedControlSolver(const HypoplasticModel& model, const ElementControl& control);

  ElementRates solve(const MaterialPointState& state) const;

 private:
  const HypoplasticModel* model_;
  ElementControl control_;
  std::array<int, 6> unknown_{};  // stress-controlled components
  int unknown_count_ = 0;
  Eigen::Matrix3d known_stretching_ = Eigen::Matrix3d::Zero();
};

}  // namespace feedflow
