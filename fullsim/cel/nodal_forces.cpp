#include "fullsim/cel/nodal_forces.hpp"

#include "fullsim/cel/quad_cell.hpp"

namespace feedflow::cel {
namespace {

// The cells around node (i, j) and the node's local index in each: cell (i, j) has it as local
// 0, (i-1, j) as 1, (i-1, j-1) as 2, (i, j-1) as 3.
template <class Visit>
void for_each_cell_around(const CelGrid& g, int i, int j, Visit&& visit) {
  if (i < g.nx && j < g.ny) visit(g.cell(i, j), 0);
  if (i > 0 && j < g.ny) visit(g.cell(i - 1, j), 1);
  if (i > 0 && j > 0) visit(g.cell(i - 1, j - 1), 2);
  if (i < g.nx && j > 0) visit(g.cell(i, j - 1), 3);
}

}  // namespace

void lump_nodal_mass(const CelGrid& grid, const CellFields& cells, NodeFields& nodes) {
  const auto n_nodes = static_cast<long>(grid.node_count());
#pragma omp parallel for schedule(static) if (n_nodes > kParallelThreshold)
  for (long k = 0; k < n_nodes; ++k) {
    const auto a = static_cast<std::size_t>(k);
    double m = 0.0;
    for_each_cell_around(grid, grid.node_i(a), grid.node_j(a),
                         [&](std::size_t c, int) { m += cells.mass[c]; });
    nodes.mass[a] = 0.25 * m;
  }
}

double bulk_viscosity_pressure(const ForceOptions& o, double density, double wave_speed,
                               double cell_size, double volume_rate) {
  double q = -o.linear_bulk_viscosity * density * wave_speed * cell_size * volume_rate;
  if (volume_rate < 0.0) {
    const double s = o.quadratic_bulk_viscosity * cell_size * volume_rate;
    q += density * s * s;
  }
  return q;
}

void assemble_nodal_forces(const CelGrid& grid, const std::vector<std::size_t>& active_cells,
                           const ForceOptions& options, const NodeVector& gravity,
                           CellFields& cells, NodeFields& nodes) {
  const double h = grid.cell_size;
  std::fill(cells.corner_force.begin(), cells.corner_force.end(), NodeVector::Zero());
  const auto n_active = static_cast<long>(active_cells.size());
#pragma omp parallel for schedule(static) if (n_active > kParallelThreshold)
  for (long k = 0; k < n_active; ++k) {
    const std::size_t c = active_cells[static_cast<std::size_t>(k)];
    const double vf = cells.volume_fraction[c];
    const double v_cell = grid.cell_volume(c);
    const double rho = cells.density(c, v_cell);
    const double cd = cells.wave_speed[c];
    const double q = bulk_viscosity_pressure(options, rho, cd, h, cells.volume_rate[c]);
    const Eigen::Matrix3d t = cells.stress[c] - q * Eigen::Matrix3d::Identity();
    const auto f = stress_nodal_forces(t, vf * v_cell, h, grid.inverse_radius(c));
    const auto nodes_of = grid.cell_nodes(c);
    CellVelocities v;
    for (int a = 0; a < kNodesPerCell; ++a) v[a] = nodes.velocity[nodes_of[a]];
    const NodeVector hg = hourglass_velocity(v);
    // Per unit depth in plane strain; per radian the column's radius weights it like the volume.
    const double c_hg = options.hourglass_coefficient * vf * rho * cd * h / 4.0 *
                        grid.column_depth(grid.cell_i(c));
    for (int a = 0; a < kNodesPerCell; ++a)
      cells.corner_force[c * kNodesPerCell + a] = f[a] - c_hg * kHourglass[a] * hg;
  }
  const auto n_nodes = static_cast<long>(grid.node_count());
#pragma omp parallel for schedule(static) if (n_nodes > kParallelThreshold)
  for (long k = 0; k < n_nodes; ++k) {
    const auto a = static_cast<std::size_t>(k);
    NodeVector f = nodes.mass[a] * gravity;
    for_each_cell_around(grid, grid.node_i(a), grid.node_j(a), [&](std::size_t c, int local) {
      f += cells.corner_force[c * kNodesPerCell + local];
    });
    nodes.force[a] = f;
  }
}

}  // namespace feedflow::cel
