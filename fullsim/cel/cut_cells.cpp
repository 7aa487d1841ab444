#include "fullsim/cel/cut_cells.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "fullsim/cel/wall_contact.hpp"

namespace feedflow::cel {
namespace {

struct Vertex {
  Eigen::Vector2d x;
  double d;  // signed distance, positive on the material side (open), 0 on the wall
};

// int w dA over the triangle's part where the linear interpolant of d is positive: w = 1 (plane
// strain) or w = x (axisymmetric, the radius). The clipped part is a polygon of at most four
// vertices; shoelace sums give its area and first moment.
double open_part_of_triangle(const std::array<Vertex, 3>& t, bool r_weighted) {
  std::array<Eigen::Vector2d, 4> p;
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const Vertex& a = t[k];
    const Vertex& b = t[(k + 1) % 3];
    if (a.d > 0.0) p[n++] = a.x;
    if ((a.d > 0.0) != (b.d > 0.0)) p[n++] = a.x + (a.d / (a.d - b.d)) * (b.x - a.x);
  }
  double area2 = 0.0, moment6 = 0.0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = p[k];
    const Eigen::Vector2d& b = p[(k + 1) % n];
    const double cross = a.x() * b.y() - b.x() * a.y();
    area2 += cross;
    moment6 += (a.x() + b.x()) * cross;
  }
  return std::abs(r_weighted ? moment6 / 6.0 : area2 / 2.0);
}

// int w ds over the open part of the segment a-b (d linear along it), w as above.
double open_part_of_segment(const Vertex& a, const Vertex& b, bool r_weighted) {
  if (a.d <= 0.0 && b.d <= 0.0) return 0.0;
  Eigen::Vector2d p = a.x, q = b.x;
  if (a.d <= 0.0) p = a.x + (a.d / (a.d - b.d)) * (b.x - a.x);
  if (b.d <= 0.0) q = a.x + (a.d / (a.d - b.d)) * (b.x - a.x);
  const double length = (q - p).norm();
  return r_weighted ? length * 0.5 * (p.x() + q.x()) : length;
}

}  // namespace

CutCellGeometry cut_cell_geometry(const CelGrid& g, const std::vector<PlacedWall>& walls,
                                  int subdivisions) {
  if (subdivisions < 1) throw std::invalid_argument("cut cells: at least one subdivision per edge");
  CutCellGeometry geo;
  geo.nx = g.nx;
  geo.ny = g.ny;
  geo.open.assign(g.cell_count(), 1.0);
  geo.x_aperture.assign(static_cast<std::size_t>(g.nx + 1) * g.ny, 1.0);
  geo.y_aperture.assign(static_cast<std::size_t>(g.nx) * (g.ny + 1), 1.0);
  if (walls.empty()) return geo;
  const double h = g.cell_size;
  const int s = subdivisions;
  const bool axi = g.axisymmetric();
  // A point is open when it lies on the material side by more than 1e-9 h (closer, it is on the
  // wall: distance 0, closed): a wall along a grid line (a bin wall through the faces of a
  // column) closes the face on it and the cells beyond, where round-off in the distance would
  // leave them slivers of 1e-17 of a cell, open to flux through a face of full aperture.
  const double on_the_wall = 1e-9 * g.cell_size;
  const auto distance = [&](const Eigen::Vector2d& x) {
    const double d = distance_to_walls(walls, x);
    return d > on_the_wall ? d : std::min(d, 0.0);
  };
  // Beyond these distances of the centre a cell (face) is wholly on one side.
  const double cell_reach = 0.5 * std::sqrt(2.0) * h * (1.0 + 1e-9);
  const double face_reach = 0.5 * h * (1.0 + 1e-9);
  const double step = h / s;

  const auto cells_n = static_cast<long>(g.cell_count());
#pragma omp parallel for schedule(dynamic, 256) if (cells_n > kParallelThreshold)
  for (long k = 0; k < cells_n; ++k) {
    const auto c = static_cast<std::size_t>(k);
    const Eigen::Vector2d centre = g.cell_centre(c);
    const double dc = distance(centre);
    if (dc >= cell_reach) continue;
    if (dc <= -cell_reach) {
      geo.open[c] = 0.0;
      continue;
    }
    const Eigen::Vector2d lo = centre.array() - 0.5 * h;
    std::vector<Vertex> lattice(static_cast<std::size_t>((s + 1) * (s + 1)));
    for (int b = 0; b <= s; ++b)
      for (int a = 0; a <= s; ++a) {
        const Eigen::Vector2d x = lo + step * Eigen::Vector2d(a, b);
        lattice[static_cast<std::size_t>(a + (s + 1) * b)] = {x, distance(x)};
      }
    double open = 0.0;
    for (int b = 0; b < s; ++b)
      for (int a = 0; a < s; ++a) {
        const auto at = [&](int da, int db) {
          return lattice[static_cast<std::size_t>(a + da + (s + 1) * (b + db))];
        };
        open += open_part_of_triangle({at(0, 0), at(1, 0), at(1, 1)}, axi);
        open += open_part_of_triangle({at(0, 0), at(1, 1), at(0, 1)}, axi);
      }
    geo.open[c] = std::clamp(open / g.cell_volume(c), 0.0, 1.0);
  }

  // Faces: the same lattice points along each face (the cells' sub-squares share them).
  const auto face_aperture = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& along_face,
                                 double full) {
    const double dm = distance(from + 0.5 * h * along_face);
    if (dm >= face_reach) return 1.0;
    if (dm <= -face_reach || full <= 0.0) return 0.0;
    double open = 0.0;
    Vertex a{from, distance(from)};
    for (int q = 1; q <= s; ++q) {
      const Eigen::Vector2d x = from + (q * step) * along_face;
      const Vertex b{x, distance(x)};
      open += open_part_of_segment(a, b, axi);
      a = b;
    }
    return std::clamp(open / full, 0.0, 1.0);
  };
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i <= g.nx; ++i) {
      const Eigen::Vector2d from = g.origin + h * Eigen::Vector2d(i, j);
      geo.x_aperture[static_cast<std::size_t>(i) + static_cast<std::size_t>(g.nx + 1) * j] =
          face_aperture(from, Eigen::Vector2d::UnitY(), g.face_area(0, i, j));
    }
  for (int j = 0; j <= g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Eigen::Vector2d from = g.origin + h * Eigen::Vector2d(i, j);
      geo.y_aperture[static_cast<std::size_t>(i) + static_cast<std::size_t>(g.nx) * j] =
          face_aperture(from, Eigen::Vector2d::UnitX(), g.face_area(1, j, i));
    }
  return geo;
}

void mark_cut_cells(const CutCellGeometry& geometry, CellFields& cells) {
  for (std::size_t c = 0; c < geometry.open.size(); ++c) {
    const double held = cells.mass[c] > 0.0 ? std::min(cells.volume_fraction[c], 1.0) : 0.0;
    cells.open_fraction[c] = std::max(geometry.open[c], held);
    if (cells.solid[c] == kSolidFixed) continue;
    cells.solid[c] = cells.open_fraction[c] <= 0.0 ? kSolidInsideWall : 0;
  }
}

}  // namespace feedflow::cel
