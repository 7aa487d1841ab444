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

CellUpdateReport update_cell_states(const PlaneStrainGrid& grid,
                                    const std::vector<std::size_t>& active_cells,
                                    const HypoplasticModel& model,
                                    const SubsteppingOptions& substepping, double dt,
                                    const NodeFields& nodes, CellFields& cells) {
  int most = 0, unconverged = 0;
  const auto n_active = static_cast<long>(active_cells.size());
#pragma omp parallel for schedule(dynamic, 64) reduction(max : most) reduction(+ : unconverged) \
    if (n_active > 1024)
  for (long k = 0; k < n_active; ++k) {
    const std::size_t c = active_cells[static_cast<std::size_t>(k)];
    const auto nodes_of = grid.cell_nodes(c);
    CellVelocities v;
    for (int a = 0; a < kNodesPerCell; ++a) v[a] = nodes.velocity[nodes_of[a]];
    const Eigen::Matrix3d l = velocity_gradient(v, grid.cell_size);
    const Eigen::Matrix3d d = 0.5 * (l + l.transpose());
    const Eigen::Matrix3d w = 0.5 * (l - l.transpose());
    cells.volume_rate[c] = d.trace();
    MaterialPointState s{cells.stress[c], cells.void_ratio[c]};
    const StepReport r = integrate_material_point(model, s, d, w, dt, substepping);
    cells.stress[c] = s.stress;
    cells.void_ratio[c] = s.void_ratio;
    most = std::max(most, r.substeps);
    if (!r.converged) ++unconverged;
  }
  return {most, unconverged};
}

}  // namespace feedflow::cel
