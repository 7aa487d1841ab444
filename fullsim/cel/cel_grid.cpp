#include "fullsim/cel/cel_grid.hpp"

#include <numbers>
#include <stdexcept>

namespace feedflow::cel {

CelGrid make_plane_strain_grid(int nx, int ny, double cell_size, const Eigen::Vector2d& origin) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("CEL grid: nx and ny must be >= 1");
  if (!(cell_size > 0.0)) throw std::invalid_argument("CEL grid: cell size must be > 0");
  CelGrid g;
  g.nx = nx;
  g.ny = ny;
  g.cell_size = cell_size;
  g.origin = origin;
  return g;
}

CelGrid make_axisymmetric_grid(int nr, int nz, double cell_size, const Eigen::Vector2d& origin) {
  if (!(origin.x() >= 0.0))
    throw std::invalid_argument("axisymmetric CEL grid: it starts at r >= 0 (origin x)");
  CelGrid g = make_plane_strain_grid(nr, nz, cell_size, origin);
  g.symmetry = GridSymmetry::axisymmetric;
  return g;
}

const char* symmetry_name(GridSymmetry symmetry) {
  return symmetry == GridSymmetry::axisymmetric ? "axisymmetric" : "plane strain";
}

double revolution_factor(const CelGrid& grid) { return grid.axisymmetric() ? 2.0 * std::numbers::pi : 1.0; }

}  // namespace feedflow::cel
