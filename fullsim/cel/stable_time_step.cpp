#include "fullsim/cel/stable_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/hypoplastic/wave_speed_bound.hpp"

namespace feedflow::cel {

TimeStepChoice stable_time_step(const CelGrid& grid,
                                const std::vector<std::size_t>& active_cells,
                                const HypoplasticModel& model, const TimeStepOptions& options,
                                const ForceOptions& viscosity, const NodeFields& nodes,
                                CellFields& cells) {
  const double h = grid.cell_size;
  const double edge = h / std::sqrt(2.0);
  TimeStepChoice choice;
  choice.dt = options.max_time_step;
  const auto n_active = static_cast<long>(active_cells.size());
  // Each thread keeps its own smallest step; they are merged by (dt, cell index), so the choice
  // does not depend on the thread count.
#pragma omp parallel if (n_active > kParallelThreshold)
  {
    TimeStepChoice mine;
    mine.dt = options.max_time_step;
#pragma omp for schedule(static) nowait
    for (long k = 0; k < n_active; ++k) {
      const std::size_t c = active_cells[static_cast<std::size_t>(k)];
      // Nothing in this loop may throw (an exception cannot leave an OpenMP region): a state
      // without a finite wave speed is handed to the blow-up guard.
      const double rho = cells.density(c, grid.cell_volume(c));
      const double cd = rho > 0.0 && std::isfinite(rho)
                            ? dilatational_wave_speed_bound(model, cells.stress[c],
                                                            cells.void_ratio[c], rho)
                            : std::numeric_limits<double>::quiet_NaN();
      cells.wave_speed[c] = cd;
      NodeVector v = NodeVector::Zero();
      for (std::size_t a : grid.cell_nodes(c)) v += nodes.velocity[a];
      const double speed = 0.25 * v.norm();
      if (!(cd >= 0.0) || !std::isfinite(cd) || !std::isfinite(speed)) {
        if (!mine.failed_cell || c < *mine.failed_cell) mine.failed_cell = c;
        continue;
      }
      mine.max_wave_speed = std::max(mine.max_wave_speed, cd);
      if (!(cd + speed > 0.0)) continue;  // no wave and at rest: no limit from this cell
      const double compression = std::min(0.0, cells.volume_rate[c]);
      const double xi = viscosity.linear_bulk_viscosity -
                        (compression < 0.0 && cd > 0.0 ? viscosity.quadratic_bulk_viscosity *
                                                 viscosity.quadratic_bulk_viscosity * (h / cd) *
                                                 compression
                                           : 0.0);
      const double damping = std::sqrt(1.0 + xi * xi) - xi;
      const double dt = cfl_time_step(edge, cd, speed, options.safety) * damping;
      if (dt < mine.dt || (dt == mine.dt && c < mine.limiting_cell)) {
        mine.dt = dt;
        mine.limiting_cell = c;
      }
    }
#pragma omp critical(feedflow_cel_time_step)
    {
      choice.max_wave_speed = std::max(choice.max_wave_speed, mine.max_wave_speed);
      if (mine.failed_cell && (!choice.failed_cell || *mine.failed_cell < *choice.failed_cell))
        choice.failed_cell = mine.failed_cell;
      if (mine.dt < choice.dt || (mine.dt == choice.dt && mine.limiting_cell < choice.limiting_cell)) {
        choice.dt = mine.dt;
        choice.limiting_cell = mine.limiting_cell;
      }
    }
  }
  return choice;
}

}  // namespace feedflow::cel
