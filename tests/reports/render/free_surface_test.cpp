// The free-surface outline of a continuum field (marching squares on the volume fraction).
#include "reports/render/free_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace feedflow::render {
namespace {

FieldGrid grid(int nx, int ny, double h) {
  FieldGrid f;
  f.cell_size = h;
  f.nx = nx;
  f.ny = ny;
  f.value.assign(static_cast<std::size_t>(nx * ny), 0.0);
  f.volume_fraction.assign(static_cast<std::size_t>(nx * ny), 0.0);
  return f;
}

// A sharp material/void interface gives an outline exactly on the cell edges between them, and
// no outline along the grid border.
TEST(FreeSurface, SharpInterfaceLiesOnCellEdges) {
  FieldGrid f = grid(6, 5, 0.1);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 6; ++i) f.volume_fraction[f.index(i, j)] = 1.0;
  }
  const auto outline = free_surface_outline(f);
  ASSERT_EQ(outline.size(), 6u);  // one segment per column
  double covered = 0.0;
  for (const OutlineSegment& s : outline) {
    EXPECT_NEAR(s.y0, 0.2, 1e-12);
    EXPECT_NEAR(s.y1, 0.2, 1e-12);
    covered += std::abs(s.x1 - s.x0);
  }
  EXPECT_NEAR(covered, 0.6, 1e-12);
}

// A disc of material (volume fraction 1 inside radius R) gives a closed outline whose points
// lie within a cell of the circle.
TEST(FreeSurface, DiscOutlineFollowsTheCircle) {
  FieldGrid f = grid(40, 40, 0.025);
  f.origin_x = -0.5;
  f.origin_y = -0.5;
  const double radius = 0.3;
  for (int j = 0; j < f.ny; ++j) {
    for (int i = 0; i < f.nx; ++i) {
      const double x = f.origin_x + (i + 0.5) * f.cell_size;
      const double y = f.origin_y + (j + 0.5) * f.cell_size;
      f.volume_fraction[f.index(i, j)] = std::hypot(x, y) < radius ? 1.0 : 0.0;
    }
  }
  const auto outline = free_surface_outline(f);
  ASSERT_FALSE(outline.empty());
  double length = 0.0;
  for (const OutlineSegment& s : outline) {
    EXPECT_NEAR(std::hypot(s.x0, s.y0), radius, f.cell_size);
    length += std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  }
  // A staircase-smoothed circle: perimeter within 10 % of 2 pi R.
  EXPECT_NEAR(length, 2.0 * std::numbers::pi * radius, 0.1 * 2.0 * std::numbers::pi * radius);
}

double filled_area(const FieldGrid& f) {
  double area = 0.0;
  for_each_filled_polygon(f, [&area](int, int, std::span<const Point2> p) {
    for (std::size_t k = 0; k < p.size(); ++k) {  // shoelace; counter-clockwise is positive
      const Point2& a = p[k];
      const Point2& b = p[(k + 1) % p.size()];
      area += 0.5 * (a.x * b.y - b.x * a.y);
    }
  });
  return area;
}

// The filled polygons cover exactly the material below a sharp interface, and about pi R^2 of
// a disc: the fill matches the outline drawn around it.
TEST(FreeSurface, FilledPolygonsCoverTheMaterial) {
  FieldGrid slab = grid(6, 5, 0.1);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 6; ++i) slab.volume_fraction[slab.index(i, j)] = 1.0;
  }
  EXPECT_NEAR(filled_area(slab), 0.6 * 0.2, 1e-12);

  FieldGrid disc = grid(40, 40, 0.025);
  disc.origin_x = -0.5;
  disc.origin_y = -0.5;
  for (int j = 0; j < disc.ny; ++j) {
    for (int i = 0; i < disc.nx; ++i) {
      const double x = disc.origin_x + (i + 0.5) * disc.cell_size;
      const double y = disc.origin_y + (j + 0.5) * disc.cell_size;
      disc.volume_fraction[disc.index(i, j)] = std::hypot(x, y) < 0.3 ? 1.0 : 0.0;
    }
  }
  EXPECT_NEAR(filled_area(disc), std::numbers::pi * 0.09, 0.05 * std::numbers::pi * 0.09);
}

// A grid with no material (or all material) has no free surface.
TEST(FreeSurface, UniformGridHasNoOutline) {
  FieldGrid f = grid(4, 4, 1.0);
  EXPECT_TRUE(free_surface_outline(f).empty());
  f.volume_fraction.assign(16, 1.0);
  EXPECT_TRUE(free_surface_outline(f).empty());
}

// A grid whose arrays do not match nx * ny is rejected.
TEST(FreeSurface, RaggedGridIsRejected) {
  FieldGrid f = grid(4, 4, 1.0);
  f.volume_fraction.pop_back();
  EXPECT_THROW(free_surface_outline(f), std::invalid_argument);
}

}  // namespace
}  // namespace feedflow::render
