#pragma once
// The forces of the Lagrangian phase (models.md 2.3 items 1, 3, 4, 8, 9): lumped nodal mass from
// the material in the cells, internal force -vf V (T - q I) b_a of every active cell with the
// bulk-viscosity pressure q (linear + quadratic), Flanagan-Belytschko viscous hourglass control
// and gravity. Cells write their corner forces; nodes gather them (no scatter races).
#include <cstddef>
#include <vector>

#include "fullsim/cel/cel_fields.hpp"

namespace feedflow::cel {

struct ForceOptions {
  double linear_bulk_viscosity = 0.06;     // b1 (Abaqus default, seed deck)
  double quadratic_bulk_viscosity = 1.2;   // b2
  double hourglass_coefficient = 0.1;      // Q_hg of C_hg = Q_hg vf rho c h / 4 (per unit depth)
};

// m_a = sum over the cells around a of M_c / 4.
void lump_nodal_mass(const CelGrid& grid, const CellFields& cells, NodeFields& nodes);

// Bulk-viscosity pressure (positive in compression) of a cell [Pa].
double bulk_viscosity_pressure(const ForceOptions& o, double density, double wave_speed,
                               double cell_size, double volume_rate);

// Fills NodeFields::force with m_a g - f_int for the active cells (uses v^{n-1/2} for the
// hourglass and the last tr D for the bulk viscosity). CellFields::wave_speed must be current.
void assemble_nodal_forces(const CelGrid& grid, const std::vector<std::size_t>& active_cells,
                           const ForceOptions& options, const NodeVector& gravity,
                           CellFields& cells, NodeFields& nodes);

}  // namespace feedflow::cel
