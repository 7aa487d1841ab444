#pragma once
// The Lagrangian phase after the forces (models.md 2.3 items 5-7): the central-difference
// velocity update v^{n+1/2} = v^{n-1/2} + (dt^{n+1} + dt^n)/2 a^n with the kinematic constraints
// (nodes without mass keep no velocity), then per active cell the velocity gradient, the
// hypoplastic integrator over dt^{n+1} and tr D for the remap. Mixed cells (models.md 2.3 item
// 7, `MixedCellRule`): equal strain rate (the material takes the cell's strain rate; the volume
// fraction of the Lagrangian cell is unchanged), or void first (the void takes the cell's
// volume change: the material is sheared at the cell's deviatoric rate and compressed only once
// the void has closed, so a free-surface cell neither inflates nor compacts by the grid motion
// around it). A nearly empty cell (vf < kNearlyEmpty) at a wall's staircase is void first under
// either rule: a speck of material there is not squeezed by the cell's motion to the densest
// state and its stiffness, which shrank the step below 1e-9 s in the drum.
#include <cstddef>
#include <vector>

#include "fullsim/cel/cel_fields.hpp"
#include "models/hypoplastic/material_point_integrator.hpp"

namespace feedflow::cel {

// Nodes lighter than this fraction of a full cell's quarter mass are void (velocity zero).
inline constexpr double kVoidNodeMassFraction = 1e-6;

// Returns the momentum dropped on void nodes (their m v + dt f) [kg m/s /m].
NodeVector advance_node_velocities(double average_dt, double void_node_mass, NodeFields& nodes);

enum class MixedCellRule { equal_strain_rate, void_first };
inline constexpr double kNearlyEmpty = 1e-3;  // at a staircase the void goes first below this vf

// The in-plane rate of deformation the material of a cell with volume fraction vf takes from
// the cell's d over dt under `rule`.
Eigen::Matrix3d material_rate_of_deformation(const Eigen::Matrix3d& d, double vf, double dt,
                                             MixedCellRule rule);

struct CellUpdateReport {
  int most_substeps = 0;
  int unconverged_cells = 0;
};

CellUpdateReport update_cell_states(const CelGrid& grid,
                                    const std::vector<std::size_t>& active_cells,
                                    const HypoplasticModel& model,
                                    const SubsteppingOptions& substepping, MixedCellRule rule,
                                    double dt, const NodeFields& nodes, CellFields& cells);

}  // namespace feedflow::cel
