#include "fullsim/cel/column_collapse_scene.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "fullsim/cel/scene_measurements.hpp"

namespace feedflow::cel {

CelScene make_column_collapse_scene(const ColumnCollapse& column, const SceneMaterial& material,
                                    double h) {
  const double l0 = column.column_length, h0 = column.aspect_ratio * l0;
  if (!(h > 0.0) || !(l0 > 0.0) || !(h0 > 0.0))
    throw std::invalid_argument("column collapse: cell size, length and height must be > 0");
  const double cells_across = l0 / h;
  if (std::abs(cells_across - std::round(cells_across)) > 1e-9)
    throw std::invalid_argument("column collapse: the column length must be a multiple of the cell size");
  CelScene s;
  s.name = "column_collapse";
  s.grid = make_plane_strain_grid(static_cast<int>(std::lround(cells_across * (1.0 + column.runout_room))),
                                  static_cast<int>(std::ceil(h0 / h)) + 2, h);
  CelOptions& o = s.options;
  o.walls = {WallCondition::free_slip, WallCondition::open, WallCondition::no_slip,
             WallCondition::open};
  o.rigid_walls = {make_half_plane_wall({l0, 0.0}, {-1.0, 0.0}, 0.0)};
  s.material.push_back({{0.0, 0.0}, {l0, h0}, material.bulk_density, material.void_ratio,
                        -10.0 * Eigen::Matrix3d::Identity()});
  s.event = {"gate removed", {0}, {}, std::numeric_limits<double>::infinity()};
  s.event_duration = 2.0;
  char line[240];
  s.plan.push_back("scene: plane-strain column collapse, free-slip back wall (symmetry plane), "
                   "no-slip base, " + grid_text(s.grid));
  std::snprintf(line, sizeof line,
                "column: L0 = %.4g m, H0 = %.4g m (a = %.3g), %.4g kg/m^3, e0 = %.4g, held by a "
                "frictionless gate during the gravity phase; event: gate removed", l0, h0,
                column.aspect_ratio, material.bulk_density, material.void_ratio);
  s.plan.push_back(line);
  return s;
}

double runout(const CelSolver& solver) {
  const std::vector<double> t = column_thickness(solver);
  const CelGrid& g = solver.grid();
  const double threshold = 0.5 * g.cell_size;
  for (int i = 0; i < g.nx; ++i) {
    if (t[i] >= threshold) continue;
    const double x = g.origin.x() + (i + 0.5) * g.cell_size;
    if (i == 0) return g.origin.x();
    const double share = (t[i - 1] - threshold) / (t[i - 1] - t[i]);  // from centre i-1
    return x - g.cell_size + share * g.cell_size;
  }
  return g.origin.x() + g.nx * g.cell_size;
}

}  // namespace feedflow::cel
