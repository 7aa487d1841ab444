#include "fullsim/cel/plane_strain_grid.hpp"

#include <stdexcept>

namespace feedflow::cel {

PlaneStrainGrid make_plane_strain_grid(int nx, int ny, double cell_size,
                                       const Eigen::Vector2d& origin) {
  if (nx < 1 || ny < 1) throw std::invalid_argument("CEL grid: nx and ny must be >= 1");
  if (!(cell_size > 0.0)) throw std::invalid_argument("CEL grid: cell size must be > 0");
  PlaneStrainGrid g;
  g.nx = nx;
  g.ny = ny;
  g.cell_size = cell_size;
  g.origin = origin;
  return g;
}

}  // namespace feedflow::cel
