#pragma once
// What the CEL scenes read off the fields for the measurements every rung shares
// (fullsim/common/*_measurement.hpp): the flow-pattern line of a hopper from the node speeds,
// the free surface of a drum bed (volume fraction 0.5) and its slope, and the deposit
// thickness along a ramp (sum of cell heights x volume fraction, as the seed's FEM). The
// discharge is measured on the run's series of the outflow ledger.
#include <vector>

#include "fullsim/cel/cel_solver.hpp"
#include "fullsim/common/flow_pattern_measurement.hpp"

namespace feedflow::cel {

// The node speeds along the grid row nearest the height `y`, from the node nearest `centre_x`
// (the centre line) towards +x, of the nodes carrying material (more than 5 % of the row's
// heaviest node): the flow-pattern line of fullsim/common/flow_pattern_measurement.hpp.
SpeedProfile speed_profile(const CelSolver& solver, double y, double centre_x = 0.0);
// Its wall-to-centre speed ratio (mass flow above 0.1).
double wall_to_centre_speed_ratio(const CelSolver& solver, double y, double centre_x = 0.0);

struct FreeSurface {
  std::vector<double> x, y;  // points where the volume fraction crosses 0.5 [m]
  double slope_angle = 0.0;  // of the least-squares line, |atan slope| [rad]
};

// The bed surface column by column between x_min and x_max: up from the lowest cell filled to
// at least half, the first crossing below half (material thrown above the bed is ignored).
FreeSurface free_surface(const CelSolver& solver, double x_min, double x_max);

// |atan| of the least-squares slope of y(x) (0 below two points or without spread in x) [rad].
double fitted_slope_angle(const std::vector<double>& x, const std::vector<double>& y);

// Thickness sum_j h vf over each column (cell centres x, thickness) [m].
std::vector<double> column_thickness(const CelSolver& solver);

}  // namespace feedflow::cel
