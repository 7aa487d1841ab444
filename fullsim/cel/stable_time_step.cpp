#include "fullsim/cel/stable_time_step.hpp"

#include <algorithm>
#include <cmath>

#include "models/hypoplastic/wave_speed_bound.hpp"

namespace feedflow::cel {

TimeStepChoice stable_time_step(const PlaneStrainGrid& grid,
                                const std::vector<std::size_t>& active_cells,
                                const HypoplasticModel& model, const TimeStepOptions& options,
                                const ForceOptions& viscosity, const NodeFields& nodes,
                                CellFields& cells) {
  const double h = grid.cell_size;
  const double edge = h / std::sqrt(2.0);
  const double v_cell = grid.cell_volume();
  TimeStepChoice choice;
  choice.dt = options.max_time_step;
  for (std::size_t c : active_cells) {
    const double rho = cells.density(c, v_cell);
    const double cd =
        dilatational_wave_speed_bound(model, cells.stress[c], cells.void_ratio[c], rho);
    cells.wave_speed[c] = cd;
    if (!(cd >= 0.0) || !std::isfinite(cd)) {
      choice.failed_cell = c;
      return choice;
    }
    choice.max_wave_speed = std::max(choice.max_wave_speed, cd);
    NodeVector v = NodeVector::Zero();
    for (std::size_t a : grid.cell_nodes(c)) v += nodes.velocity[a];
    const double speed = 0.25 * v.norm();
    const double xi = viscosity.linear_bulk_viscosity -
                      viscosity.quadratic_bulk_viscosity * viscosity.quadratic_bulk_viscosity *
                          (h / cd) * std::min(0.0, cells.volume_rate[c]);
    const double damping = std::sqrt(1.0 + xi * xi) - xi;
    const double dt = cfl_time_step(edge, cd, speed, options.safety) * damping;
    if (dt < choice.dt) {
      choice.dt = dt;
      choice.limiting_cell = c;
    }
  }
  return choice;
}

}  // namespace feedflow::cel
