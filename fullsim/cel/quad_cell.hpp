#pragma once
// The one-point quadrilateral element on a square cell (models.md 2.3 items 2, 6, 8): the
// uniform-gradient vectors b_a = (xi_a, eta_a) / (2 h), the velocity gradient L = sum_a v_a (x) b_a
// and the single hourglass base vector Gamma = xi eta = (+1, -1, +1, -1), which on a rectangle is
// orthogonal to every linear velocity field (Flanagan & Belytschko 1981).
#include <Eigen/Core>
#include <array>

#include "fullsim/cel/plane_strain_grid.hpp"

namespace feedflow::cel {

inline constexpr std::array<double, kNodesPerCell> kXi = {-1.0, 1.0, 1.0, -1.0};
inline constexpr std::array<double, kNodesPerCell> kEta = {-1.0, -1.0, 1.0, 1.0};
inline constexpr std::array<double, kNodesPerCell> kHourglass = {1.0, -1.0, 1.0, -1.0};

using CellVelocities = std::array<NodeVector, kNodesPerCell>;

inline NodeVector gradient_vector(int local_node, double cell_size) {
  return NodeVector(kXi[local_node], kEta[local_node]) / (2.0 * cell_size);
}

// Full 3x3 velocity gradient L_ij = dv_i/dx_j of the plane-strain cell (third row/column zero).
inline Eigen::Matrix3d velocity_gradient(const CellVelocities& v, double cell_size) {
  Eigen::Matrix3d l = Eigen::Matrix3d::Zero();
  for (int a = 0; a < kNodesPerCell; ++a) {
    const NodeVector b = gradient_vector(a, cell_size);
    l.topLeftCorner<2, 2>() += v[a] * b.transpose();
  }
  return l;
}

// Hourglass velocity q = sum_a v_a Gamma_a [m/s].
inline NodeVector hourglass_velocity(const CellVelocities& v) {
  NodeVector q = NodeVector::Zero();
  for (int a = 0; a < kNodesPerCell; ++a) q += kHourglass[a] * v[a];
  return q;
}

// Nodal forces -V T b_a of a cell stress (tension positive) on its material volume V.
inline std::array<NodeVector, kNodesPerCell> stress_nodal_forces(const Eigen::Matrix3d& stress,
                                                                 double volume, double cell_size) {
  std::array<NodeVector, kNodesPerCell> f;
  const Eigen::Matrix2d t = stress.topLeftCorner<2, 2>();
  for (int a = 0; a < kNodesPerCell; ++a) f[a] = -volume * (t * gradient_vector(a, cell_size));
  return f;
}

}  // namespace feedflow::cel
