#include "fullsim/cel/lagrangian_phase.hpp"

#include <algorithm>

#include "fullsim/cel/box_walls.hpp"
#include "fullsim/cel/quad_cell.hpp"

namespace feedflow::cel {

NodeVector advance_node_velocities(double average_dt, double void_node_mass, NodeFields& nodes) {
  NodeVector dropped = NodeVector::Zero();
  for (std::size_t a = 0; a < nodes.velocity.size(); ++a) {
    if (nodes.mass[a] > void_node_mass) {
      nodes.velocity[a] += (average_dt / nodes.mass[a]) * nodes.force[a];
    } else {
      dropped += nodes.mass[a] * nodes.velocity[a] + average_dt * nodes.force[a];
      nodes.velocity[a].setZero();
    }
  }
  apply_node_constraints(nodes);
  return dropped;
}

Eigen::Matrix3d material_rate_of_deformation(const Eigen::Matrix3d& d, double vf, double dt,
                                             MixedCellRule rule) {
  if (rule == MixedCellRule::equal_strain_rate || vf >= 1.0 || !(vf > 0.0)) return d;
  const double cell_rate = d.trace();  // the hoop rate d(2, 2) too (axisymmetric)
  // The void (1 - vf of the cell) takes the volume change; compression beyond it goes to the
  // material, at the rate that brings it to the cell's new volume.
  const double closing = -cell_rate * dt - (1.0 - vf);
  const double material_rate = closing > 0.0 ? -closing / (vf * dt) : 0.0;
  Eigen::Matrix3d m = d;
  const double shift = 0.5 * (cell_rate - material_rate);
  m(0, 0) -= shift;
  m(1, 1) -= shift;
  return m;
}

CellUpdateReport update_cell_states(const CelGrid& grid,
                                    const std::vector<std::size_t>& active_cells,
                                    const HypoplasticModel& model,
                                    const SubsteppingOptions& substepping, MixedCellRule rule,
                                    double dt, const NodeFields& nodes, CellFields& cells) {
  int most = 0, unconverged = 0;
  const auto n_active = static_cast<long>(active_cells.size());
#pragma omp parallel for schedule(dynamic, 64) reduction(max : most) reduction(+ : unconverged) \
    if (n_active > kParallelThreshold)
  for (long k = 0; k < n_active; ++k) {
    const std::size_t c = active_cells[static_cast<std::size_t>(k)];
    const auto nodes_of = grid.cell_nodes(c);
    CellVelocities v;
    for (int a = 0; a < kNodesPerCell; ++a) v[a] = nodes.velocity[nodes_of[a]];
    const Eigen::Matrix3d l = velocity_gradient(v, grid.cell_size, grid.inverse_radius(c));
    const Eigen::Matrix3d d = 0.5 * (l + l.transpose());
    const Eigen::Matrix3d w = 0.5 * (l - l.transpose());
    cells.volume_rate[c] = d.trace();
    MaterialPointState s{cells.stress[c], cells.void_ratio[c]};
    const double vf = cells.open_volume_fraction(c);  // a cut cell's void is in its open part
    const MixedCellRule cell_rule =
        vf < kNearlyEmpty && at_staircase(grid, cells, c) ? MixedCellRule::void_first : rule;
    const Eigen::Matrix3d dm = material_rate_of_deformation(d, vf, dt, cell_rule);
    const StepReport r = integrate_material_point(model, s, dm, w, dt, substepping);
    cells.stress[c] = s.stress;
    cells.void_ratio[c] = s.void_ratio;
    most = std::max(most, r.substeps);
    if (!r.converged) ++unconverged;
  }
  return {most, unconverged};
}

}  // namespace feedflow::cel
