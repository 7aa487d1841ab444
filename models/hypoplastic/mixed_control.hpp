#pragma once
// Mixed stress/strain control of a homogeneous element: each of the six tensor components
// (xx, yy, zz, xy, yz, zx) has either its stretching D_ij or its stress rate dT_ij/dt prescribed;
// the unknown stretching components are solved from the rate law
//   dT/dt = T°(T, e, D) + W T - T W   (Jaumann, models.md 1.1)
// with GSL's hybrid Newton solver and the analytic Jacobian of the rate law.
#include <array>
#include <memory>

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

// Solves for the unknown stretching components. Holds the GSL solver and the last solution (the
// next solve starts from it). Throws NumericalFailure when the solve does not converge.
class MixedControlSolver {
 public:
  MixedControlSolver(const HypoplasticModel& model, const ElementControl& control);
  ~MixedControlSolver();
  MixedControlSolver(const MixedControlSolver&) = delete;
  MixedControlSolver& operator=(const MixedControlSolver&) = delete;

  ElementRates solve(const MaterialPointState& state);

  struct Workspace;  // opaque: GSL state and the last solution

 private:
  std::unique_ptr<Workspace> w_;
};

}  // namespace feedflow
