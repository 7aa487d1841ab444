#pragma once
// Objective update of the stress for the spin W over a step dt (models.md 1.1, 1.6): the
// Hughes-Winget rotation Q = (I - dt W/2)^-1 (I + dt W/2), T <- Q T Q^T, which is exactly
// orthogonal for a skew W and first-order equivalent to the Jaumann rate dT/dt = T° + W T - T W.
#include <Eigen/Core>
#include <Eigen/LU>

namespace feedflow {

inline Eigen::Matrix3d hughes_winget_rotation(const Eigen::Matrix3d& spin, double dt) {
  const Eigen::Matrix3d half = (0.5 * dt) * spin;
  return (Eigen::Matrix3d::Identity() - half).inverse() * (Eigen::Matrix3d::Identity() + half);
}

// Rotates `stress` in place; a zero spin leaves it untouched (and costs nothing).
inline void rotate_objectively(Eigen::Matrix3d& stress, const Eigen::Matrix3d& spin, double dt) {
  if (spin.isZero(0.0)) return;
  const Eigen::Matrix3d q = hughes_winget_rotation(spin, dt);
  const Eigen::Matrix3d rotated = q * stress * q.transpose();
  stress = 0.5 * (rotated + rotated.transpose());  // keep it exactly symmetric
}

}  // namespace feedflow
