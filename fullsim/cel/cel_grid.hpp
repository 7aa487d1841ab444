#pragma once
// The fixed Eulerian grid of the CEL solver: nx x ny square cells of edge h, nodes at the cell
// corners, in one of two symmetries:
// - plane strain: (x, y) with unit depth; every mass, volume and force is per metre of depth;
// - axisymmetric: (r, z) = (x, y) about the axis x = 0 (the grid starts at r = origin.x >= 0);
//   every mass, volume and force is per radian, a cell's volume is the r-weighted area
//   integral h^2 r_c (exact for a cell: int r dr over it is h r_c) and the hoop strain rate
//   v_r / r and hoop stress enter the element (quad_cell.hpp).
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

enum class GridSymmetry { plane_strain, axisymmetric };

struct CelGrid {
  int nx = 0;              // cells along x (r)
  int ny = 0;              // cells along y (z, up, against gravity)
  double cell_size = 0.0;  // h [m]
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // lower-left corner [m]
  GridSymmetry symmetry = GridSymmetry::plane_strain;

  bool axisymmetric() const { return symmetry == GridSymmetry::axisymmetric; }
  std::size_t cell_count() const { return static_cast<std::size_t>(nx) * ny; }
  std::size_t node_count() const { return static_cast<std::size_t>(nx + 1) * (ny + 1); }
  std::size_t cell(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j; }
  std::size_t node(int i, int j) const { return static_cast<std::size_t>(i) + static_cast<std::size_t>(nx + 1) * j; }
  int cell_i(std::size_t c) const { return static_cast<int>(c % static_cast<std::size_t>(nx)); }
  int cell_j(std::size_t c) const { return static_cast<int>(c / static_cast<std::size_t>(nx)); }
  int node_i(std::size_t a) const { return static_cast<int>(a % static_cast<std::size_t>(nx + 1)); }
  int node_j(std::size_t a) const { return static_cast<int>(a / static_cast<std::size_t>(nx + 1)); }

  // The out-of-plane measure at x: 1 m (plane strain) or the radius x per radian.
  double depth_at(double x) const { return axisymmetric() ? x : 1.0; }
  // Of cell column i: at its centre (the r-weighted mean over the column's width).
  double column_depth(int i) const { return depth_at(origin.x() + (i + 0.5) * cell_size); }
  // [m^3/m] or [m^3/rad]
  double cell_volume(std::size_t c) const { return cell_size * cell_size * column_depth(cell_i(c)); }
  // The face normal to `axis` on node line `along` (axis 0: x = origin.x + along h) in cell line
  // `across` [m^2/m] or [m^2/rad].
  double face_area(int axis, int along, int across) const {
    return cell_size * (axis == 0 ? depth_at(origin.x() + along * cell_size) : column_depth(across));
  }
  // 1 / r at cell c's centre (the hoop term's weight); 0 in plane strain [1/m].
  double inverse_radius(std::size_t c) const { return axisymmetric() ? 1.0 / column_depth(cell_i(c)) : 0.0; }

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
CelGrid make_plane_strain_grid(int nx, int ny, double cell_size,
                               const Eigen::Vector2d& origin = Eigen::Vector2d::Zero());
// (r, z) from r = origin.x: the axis when origin.x = 0 (its face must be free slip: the
// symmetry line), an annulus beyond it. Throws std::invalid_argument also for origin.x < 0.
CelGrid make_axisymmetric_grid(int nr, int nz, double cell_size,
                               const Eigen::Vector2d& origin = Eigen::Vector2d::Zero());

// "plane strain" or "axisymmetric" (checkpoints, snapshot files, plans).
const char* symmetry_name(GridSymmetry symmetry);

// The full body the grid's per-depth quantities stand for: 2 pi (per radian -> the whole
// revolution) or 1 (per metre of depth stays per metre).
double revolution_factor(const CelGrid& grid);

}  // namespace feedflow::cel
