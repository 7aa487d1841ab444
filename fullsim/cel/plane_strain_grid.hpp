#pragma once
// The fixed Eulerian grid of the plane-strain CEL solver: nx x ny square cells of edge h, unit
// depth (every mass, volume and force is per metre of depth), nodes at the cell corners.
// Everything that knows the grid is two-dimensional lives here and in quad_cell.hpp, so a
// hexahedral variant replaces these two headers and keeps the phases (models.md 2.2).
#include <Eigen/Core>
#include <array>
#include <cstddef>

namespace feedflow::cel {

inline constexpr int kDimension = 2;
inline constexpr int kNodesPerCell = 4;
// Loops over cells or nodes run on OpenMP threads above this many items (each item's result
// is independent of the thread count: the runs are the same bits on any number of threads).
inline constexpr long kParallelThreshold = 1024;
using NodeVector = Eigen::Vector2d;

struct PlaneStrainGrid {
  int nx = 0;              // cells along x
  int ny = 0;              // cells along y (up, against gravity)
  double cell_size = 0.0;  // h [m]
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // lower-left corner [m]

  std::size_t cell_count() const { return static_cast<std::size_t>(nx) * ny; }
  std::size_t node_count() const { return static_cast<std::size_t>(nx + 1) * (ny + 1); }
  std::size_t cell(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j; }
  std::size_t node(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx + 1) * j; }
  int cell_i(std::size_t c) const { return static_cast<int>(c % static_cast<std::size_t>(nx)); }
  int cell_j(std::size_t c) const { return static_cast<int>(c / static_cast<std::size_t>(nx)); }
  int node_i(std::size_t a) const { return static_cast<int>(a % static_cast<std::size_t>(nx + 1)); }
  int node_j(std::size_t a) const { return static_cast<int>(a / static_cast<std::size_t>(nx + 1)); }
  double cell_volume() const { return cell_size * cell_size; }  // per unit depth [m^3/m]
  double face_area() const { return cell_size; }                // per unit depth [m^2/m]

  // Corner nodes counter-clockwise from the lower left: (i,j), (i+1,j), (i+1,j+1), (i,j+1).
  std::array<std::size_t, kNodesPerCell> cell_nodes(std::size_t c) const {
    const int i = cell_i(c), j = cell_j(c);
    return {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
  }
  Eigen::Vector2d cell_centre(std::size_t c) const {
    return origin + cell_size * Eigen::Vector2d(cell_i(c) + 0.5, cell_j(c) + 0.5);
  }
  Eigen::Vector2d node_position(std::size_t a) const {
    return origin + cell_size * Eigen::Vector2d(node_i(a), node_j(a));
  }
};

// Throws std::invalid_argument unless nx, ny >= 1 and h > 0.
PlaneStrainGrid make_plane_strain_grid(int nx, int ny, double cell_size,
                                       const Eigen::Vector2d& origin = Eigen::Vector2d::Zero());

}  // namespace feedflow::cel
