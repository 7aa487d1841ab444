#include "fullsim/cel/drum_bed_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fullsim/common/drum_surface_fit.hpp"

namespace feedflow::cel {

double surface_height(const FreeSurface& surface, double station) {
  const std::vector<double>& x = surface.x;  // ascending (drum_surface walks across)
  for (std::size_t p = 1; p < x.size(); ++p)
    if (x[p - 1] <= station && station <= x[p]) {
      const double w = x[p] > x[p - 1] ? (station - x[p - 1]) / (x[p] - x[p - 1]) : 0.0;
      return (1.0 - w) * surface.y[p - 1] + w * surface.y[p];
    }
  return std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> surface_heights(const FreeSurface& surface,
                                    const std::vector<double>& stations) {
  std::vector<double> u(stations.size());
  for (std::size_t k = 0; k < stations.size(); ++k) u[k] = surface_height(surface, stations[k]);
  return u;
}

ChordProfile chord_profile(const FreeSurface& surface, const std::vector<double>& fractions) {
  ChordProfile p;
  p.height.assign(fractions.size(), 0.0);
  if (surface.x.size() < 2) return p;
  p.found = true;
  p.low = surface.x.front();
  p.high = surface.x.back();
  std::vector<double> at(fractions.size());
  for (std::size_t k = 0; k < at.size(); ++k)
    at[k] = 0.5 * (p.low + p.high) + 0.5 * fractions[k] * (p.high - p.low);
  p.height = surface_heights(surface, at);  // inside the chord: every station between two points
  return p;
}

DrumBedState drum_bed_state(const CelSolver& solver, const DrumSection& section,
                            const FreeSurface& surface, double speed) {
  const CelGrid& g = solver.grid();
  const CellFields& cells = solver.cells();
  const double t = solver.time(), h = g.cell_size, R = section.radius;
  const NodeVector up = -solver.frame().gravity(solver.options().gravity, t).normalized();
  const NodeVector across(up.y(), -up.x());
  std::vector<SurfacePoint> points(surface.x.size());
  for (std::size_t k = 0; k < points.size(); ++k) points[k] = {surface.x[k], surface.y[k]};
  // Whether a cell lies clear of the bed: no cell within two cells of it is at least half full.
  const auto clear_of_bed = [&](std::size_t c) {
    const int i = g.cell_i(c), j = g.cell_j(c);
    for (int jj = std::max(0, j - 2); jj <= std::min(g.ny - 1, j + 2); ++jj)
      for (int ii = std::max(0, i - 2); ii <= std::min(g.nx - 1, i + 2); ++ii)
        if (cells.volume_fraction[g.cell(ii, jj)] >= 0.5) return false;
    return true;
  };
  // Velocities in a turning frame are relative to the shell; the laboratory's add the turn.
  const bool relative = solver.frame().turning(t);
  double mass = 0.0, airborne = 0.0, over_top = 0.0, solid = 0.0, shell = 0.0, shell_speed = 0.0;
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    const double m = cells.mass[c];
    if (!(m > 0.0) || cells.solid[c]) continue;
    const Eigen::Vector2d d = g.cell_centre(c) - section.centre;
    const double radial = d.norm(), s = d.dot(across), u = d.dot(up);
    NodeVector v = NodeVector::Zero();
    for (std::size_t a : g.cell_nodes(c)) v += 0.25 * solver.nodes().velocity[a];
    const NodeVector turn = speed * NodeVector(-d.y(), d.x());  // the shell's rigid turn at d
    const NodeVector v_lab = relative ? NodeVector(v + turn) : v;
    mass += m;
    if (radial < R - 2.0 * h && clear_of_bed(c)) airborne += m;
    if (u > 0.8 * R) over_top += m;
    if ((v_lab - turn).norm() < 0.1 * std::abs(speed) * R) solid += m;
    if (radial > R - h && u < surface_height(surface, s) - 2.0 * h) {  // false beyond the chord
      shell += m;
      shell_speed += m * v_lab.dot(NodeVector(-d.y(), d.x())) / radial;
    }
  }
  DrumBedState state;
  state.surface_bulge = fit_drum_surface(points, R).bulge;
  if (!(mass > 0.0)) return state;
  state.airborne_fraction = airborne / mass;
  state.over_top_fraction = over_top / mass;
  state.solid_body_fraction = speed != 0.0 ? solid / mass : 0.0;
  state.shell_speed_ratio = shell > 0.0 && speed != 0.0 ? shell_speed / shell / (speed * R) : 1.0;
  return state;
}

}  // namespace feedflow::cel
