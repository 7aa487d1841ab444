#include "fullsim/cel/scene_measurements.hpp"

#include <algorithm>
#include <cmath>

namespace feedflow::cel {
SpeedProfile speed_profile(const CelSolver& solver, double y, double centre_x) {
  const auto& g = solver.grid();
  const int j = std::clamp(static_cast<int>(std::lround((y - g.origin.y()) / g.cell_size)), 0, g.ny);
  const int i0 = std::clamp(static_cast<int>(std::lround((centre_x - g.origin.x()) / g.cell_size)), 0, g.nx);
  // A node's mass per unit of its depth (axisymmetric: over the mean radius of the columns
  // beside it, so the nodes near the axis are not light for their small radius).
  const auto filling = [&](int i) {
    const int lo = std::max(i - 1, 0), hi = std::min(i, g.nx - 1);
    return solver.nodes().mass[g.node(i, j)] / (0.5 * (g.column_depth(lo) + g.column_depth(hi)));
  };
  double heaviest = 0.0;
  for (int i = i0; i <= g.nx; ++i) heaviest = std::max(heaviest, filling(i));
  const double light = 0.05 * heaviest;  // nodes of nearly empty cells do not count
  SpeedProfile line;
  for (int i = i0; i <= g.nx; ++i) {
    const std::size_t a = g.node(i, j);
    if (filling(i) <= light) continue;
    line.offset.push_back((i - i0) * g.cell_size);
    line.speed.push_back(solver.nodes().velocity[a].norm());
  }
  return line;
}

double wall_to_centre_speed_ratio(const CelSolver& solver, double y, double centre_x) {
  return feedflow::wall_to_centre_speed_ratio(speed_profile(solver, y, centre_x)).ratio;
}

FreeSurface free_surface(const CelSolver& solver, double x_min, double x_max) {
  const auto& g = solver.grid();
  const auto& vf = solver.cells().volume_fraction;
  FreeSurface f;
  for (int i = 0; i < g.nx; ++i) {
    const double x = g.origin.x() + (i + 0.5) * g.cell_size;
    if (x < x_min || x > x_max) continue;
    int j = 0;  // up from the bottom: the first filled cell, then the first one below half
    while (j < g.ny && vf[g.cell(i, j)] < 0.5) ++j;
    while (j + 1 < g.ny && vf[g.cell(i, j + 1)] >= 0.5) ++j;
    if (j + 1 >= g.ny) continue;  // no filled cell, or filled to the top
    const double below = vf[g.cell(i, j)], here = vf[g.cell(i, j + 1)];
    const double y0 = g.origin.y() + (j + 0.5) * g.cell_size;
    f.x.push_back(x);
    f.y.push_back(y0 + g.cell_size * (below - 0.5) / (below - here));
  }
  f.slope_angle = fitted_slope_angle(f.x, f.y);
  return f;
}

double fitted_slope_angle(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = std::min(x.size(), y.size());
  if (n < 2) return 0.0;
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < n; ++k) mx += x[k], my += y[k];
  mx /= static_cast<double>(n), my /= static_cast<double>(n);
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k = 0; k < n; ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  return sxx > 0.0 ? std::abs(std::atan(sxy / sxx)) : 0.0;
}

std::vector<double> column_thickness(const CelSolver& solver) {
  const auto& g = solver.grid();
  std::vector<double> t(g.nx, 0.0);
  for (int i = 0; i < g.nx; ++i)
    for (int j = 0; j < g.ny; ++j) t[i] += g.cell_size * solver.cells().volume_fraction[g.cell(i, j)];
  return t;
}

}  // namespace feedflow::cel
