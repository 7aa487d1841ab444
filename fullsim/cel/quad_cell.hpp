#pragma once
// The one-point quadrilateral element on a square cell (models.md 2.3 items 2, 6, 8): the
// uniform-gradient vectors b_a = (xi_a, eta_a) / (2 h), the velocity gradient L = sum_a v_a (x) b_a
// and the single hourglass base vector Gamma = xi eta = (+1, -1, +1, -1), which on a rectangle is
// orthogonal to every linear velocity field (Flanagan & Belytschko 1981). Axisymmetric cells add
// the hoop terms at the centre (one-point quadrature, volume weighted): the hoop strain rate
// L_thth = v_r / r with v_r the mean of the corner velocities (N_a = 1/4), and in the nodal
// forces the hoop stress's radial share -V T_thth N_a / r. With them the forces are the virtual
// power of the stress: sum_a f_a . v_a = -V T : D, and a uniform stress is in equilibrium at
// every interior node. `inverse_radius` is 1 / r_c (0: plane strain, no hoop terms).
#include <Eigen/Core>
#include <array>

#include "fullsim/cel/cel_grid.hpp"

namespace feedflow::cel {

inline constexpr std::array<double, kNodesPerCell> kXi = {-1.0, 1.0, 1.0, -1.0};
inline constexpr std::array<double, kNodesPerCell> kEta = {-1.0, -1.0, 1.0, 1.0};
inline constexpr std::array<double, kNodesPerCell> kHourglass = {1.0, -1.0, 1.0, -1.0};

using CellVelocities = std::array<NodeVector, kNodesPerCell>;

inline NodeVector gradient_vector(int local_node, double cell_size) {
  return NodeVector(kXi[local_node], kEta[local_node]) / (2.0 * cell_size);
}

// Full 3x3 velocity gradient L_ij = dv_i/dx_j of the cell: in plane strain the third row and
// column are zero; axisymmetric, L_33 = v_r / r (the hoop strain rate).
inline Eigen::Matrix3d velocity_gradient(const CellVelocities& v, double cell_size,
                                         double inverse_radius = 0.0) {
  Eigen::Matrix3d l = Eigen::Matrix3d::Zero();
  for (int a = 0; a < kNodesPerCell; ++a) {
    const NodeVector b = gradient_vector(a, cell_size);
    l.topLeftCorner<2, 2>() += v[a] * b.transpose();
  }
  if (inverse_radius != 0.0)
    l(2, 2) = 0.25 * (v[0].x() + v[1].x() + v[2].x() + v[3].x()) * inverse_radius;
  return l;
}

// Hourglass velocity q = sum_a v_a Gamma_a [m/s].
inline NodeVector hourglass_velocity(const CellVelocities& v) {
  NodeVector q = NodeVector::Zero();
  for (int a = 0; a < kNodesPerCell; ++a) q += kHourglass[a] * v[a];
  return q;
}

// Nodal forces -V T b_a of a cell stress (tension positive) on its material volume V, and
// axisymmetric the hoop share -V T_33 / (4 r) on the radial components.
inline std::array<NodeVector, kNodesPerCell> stress_nodal_forces(const Eigen::Matrix3d& stress,
                                                                 double volume, double cell_size,
                                                                 double inverse_radius = 0.0) {
  std::array<NodeVector, kNodesPerCell> f;
  const Eigen::Matrix2d t = stress.topLeftCorner<2, 2>();
  for (int a = 0; a < kNodesPerCell; ++a) f[a] = -volume * (t * gradient_vector(a, cell_size));
  if (inverse_radius != 0.0) {
    const double hoop = 0.25 * volume * stress(2, 2) * inverse_radius;
    for (int a = 0; a < kNodesPerCell; ++a) f[a].x() -= hoop;
  }
  return f;
}

}  // namespace feedflow::cel
