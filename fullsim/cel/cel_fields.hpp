#pragma once
// The state of the CEL solver as arrays (data-oriented, one entry per cell or node; models.md
// 2.2): per cell the material volume fraction, mass, full 3x3 stress, void ratio and a solid flag
// (cells inside walls); per node the velocity v^{n-1/2}, the lumped mass and the kinematic
// constraint. Lists of active cells and nodes let void cost nothing.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "fullsim/cel/cel_grid.hpp"

namespace feedflow::cel {

// CellFields::solid values: cells fixed by CelSolver::set_solid (no slip on their nodes) and
// cells inside a rigid wall (their nodes are left to the wall contact).
inline constexpr std::uint8_t kSolidFixed = 1;
inline constexpr std::uint8_t kSolidInsideWall = 2;

struct CellFields {
  std::vector<double> volume_fraction;   // material volume / cell volume, in [0, 1] [-]
  std::vector<double> mass;              // material mass per unit depth [kg/m] (per radian [kg/rad] axisymmetric)
  std::vector<Eigen::Matrix3d> stress;   // Cauchy stress, tension positive [Pa]
  std::vector<double> void_ratio;        // [-]
  std::vector<std::uint8_t> solid;       // kSolid*: no material, no transport; 0: fluid
  std::vector<double> open_fraction;     // open volume / cell volume: below 1 in cut cells only
  // Per step, written by the phases:
  std::vector<double> wave_speed;        // c_d bound of the last time-step pass [m/s]
  std::vector<double> volume_rate;       // tr D of the last Lagrangian phase [1/s]
  std::vector<NodeVector> corner_force;  // kNodesPerCell forces per cell [N/m]

  void resize(std::size_t cells);
  double density(std::size_t c, double cell_volume) const {  // rho = M / (vf V) [kg/m^3]
    return volume_fraction[c] > 0.0 ? mass[c] / (volume_fraction[c] * cell_volume) : 0.0;
  }
  // Material volume over the cell's open volume (the fill a cut cell's material sees) [-].
  double open_volume_fraction(std::size_t c) const {
    return open_fraction[c] > 0.0 ? volume_fraction[c] / open_fraction[c] : volume_fraction[c];
  }
};

// Whether cell c touches a solid cell across a face or a corner, or is cut by a wall: a cell at a
// wall's staircase.
bool at_staircase(const CelGrid& grid, const CellFields& cells, std::size_t c);

// Kinematic constraint of a node: which velocity components are prescribed (to zero).
enum class NodeConstraint : std::uint8_t { free = 0, fixed_x = 1, fixed_y = 2, fixed = 3 };

struct NodeFields {
  std::vector<NodeVector> velocity;      // v^{n-1/2} [m/s]
  std::vector<double> mass;              // lumped [kg/m]
  std::vector<NodeVector> force;         // f_ext - f_int of the current step [N/m]
  std::vector<std::uint8_t> constraint;  // NodeConstraint bits

  void resize(std::size_t nodes);
};

}  // namespace feedflow::cel
