#pragma once
// The explicit time step of the CEL solver (models.md 5.2), recomputed every step: per active
// cell the hypoplastic tangent bound c_d = sqrt(M_b / rho) (wave_speed_bound.hpp) and
// dt_c = s (h / sqrt 2) / (c_d + |v|) (sqrt(1 + xi^2) - xi), the one-point square-element limit
// with lumped mass reduced by the bulk-viscosity damping ratio
// xi = b1 - b2^2 (h / c_d) min(0, tr D). The step is the smallest dt_c, capped.
#include <cstddef>
#include <optional>
#include <vector>

#include "fullsim/cel/cel_fields.hpp"
#include "fullsim/cel/nodal_forces.hpp"
#include "models/hypoplastic/hypoplastic_model.hpp"

namespace feedflow::cel {

struct TimeStepOptions {
  double safety = 0.8;           // s: the Courant number ([cel] time_step_safety, at most 1)
  double max_time_step = 1e-3;   // cap [s] (loose, nearly stress-free material is very soft)
};

struct TimeStepChoice {
  double dt = 0.0;                // [s]
  std::size_t limiting_cell = 0;  // the cell with the smallest dt_c (0 when none is active)
  double max_wave_speed = 0.0;    // largest c_d [m/s]
  // A cell whose state gives no finite wave speed (dt is then not valid): the blow-up guard's.
  std::optional<std::size_t> failed_cell;
};

// Writes CellFields::wave_speed of the active cells.
TimeStepChoice stable_time_step(const CelGrid& grid,
                                const std::vector<std::size_t>& active_cells,
                                const HypoplasticModel& model, const TimeStepOptions& options,
                                const ForceOptions& viscosity, const NodeFields& nodes,
                                CellFields& cells);

}  // namespace feedflow::cel
