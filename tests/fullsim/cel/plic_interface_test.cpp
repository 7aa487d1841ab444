// PLIC (Youngs) interface reconstruction: the cut geometry against hand-computed areas, and a
// square and a disc of material translated by the remap alone in a uniform velocity field:
// shape kept far better than with the donor cell, mass to round-off, 0 <= vf <= 1 (models.md
// 2.4 item 2c).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "fullsim/cel/plic_interface.hpp"
#include "fullsim/cel/remap_phase.hpp"

namespace feedflow::cel {
namespace {

// A 45 deg line through a unit square leaving a quarter of it: the triangle below x + y = c with
// c = sqrt(1/2); the slab x in [0, 0.5] holds the triangle's part there (area c^2/2 - (c-0.5)^2/2).
TEST(PlicInterface, CutOfASquareMatchesGeometry) {
  const NodeVector n = NodeVector(1.0, 1.0).normalized();
  const CutRectangle cut = cut_rectangle(1.0, 1.0, n, 0.25);
  const double c = std::sqrt(0.5);
  EXPECT_NEAR(cut.alpha, c / std::sqrt(2.0), 1e-13);
  EXPECT_NEAR(material_area(cut, 0.0, 1.0), 0.25, 1e-13);
  EXPECT_NEAR(material_area(cut, 0.0, 0.5), 0.5 * c * c - 0.5 * (c - 0.5) * (c - 0.5), 1e-13);
  // A vertical interface (normal +x) at vf 0.3 of a 2 x 1 rectangle: all material in x < 0.6.
  const CutRectangle wall = cut_rectangle(2.0, 1.0, NodeVector(1.0, 0.0), 0.3);
  EXPECT_NEAR(material_area(wall, 1.4, 2.0), 0.0, 1e-13);
  EXPECT_NEAR(material_area(wall, 0.0, 0.5), 0.5, 1e-13);
}

// Youngs' normal of a half-filled block points from the material into the void.
TEST(PlicInterface, YoungsNormalPointsIntoTheVoid) {
  const std::array<double, 9> below = {1, 1, 1, 0.5, 0.5, 0.5, 0, 0, 0};  // material at dj = -1
  const NodeVector n = youngs_normal(below);
  EXPECT_NEAR(n.x(), 0.0, 1e-15);
  EXPECT_NEAR(n.y(), 1.0, 1e-15);
  EXPECT_TRUE(youngs_normal({1, 1, 1, 1, 1, 1, 1, 1, 1}).isZero());
}

// Remap alone in a uniform velocity field (open box faces, no flux there).
struct Translation {
  CelGrid grid;
  CellFields cells;
  NodeFields nodes;
  RemapPhase remap;
  RemapReport last{};
  double largest = 0.0, smallest = 1.0, removed = 0.0;
  Translation(int n, double h, MaterialFlux flux)
      : grid(make_plane_strain_grid(n, n, h)), remap([&] {
          RemapOptions o;
          o.material_flux = flux;
          return o;
        }()) {
    cells.resize(grid.cell_count());
    nodes.resize(grid.node_count());
  }
  void run(const NodeVector& v, double dt, int steps) {
    const BoxWalls open{WallCondition::open, WallCondition::open, WallCondition::open,
                        WallCondition::open};
    for (int k = 0; k < steps; ++k) {
      for (auto& u : nodes.velocity) u = v;
      last = remap.remap(grid, open, dt, k % 2 == 0, 0.0, cells, nodes);
      largest = std::max(largest, last.largest_volume_fraction);
      smallest = std::min(smallest, last.smallest_volume_fraction);
      removed += last.removed_mass;
    }
  }
};

// Area share of a cell inside a shape, by 20 x 20 sub-samples.
double covered(const CelGrid& g, std::size_t c, const std::function<bool(NodeVector)>& in) {
  int k = 0;
  const NodeVector lo = g.cell_centre(c).array() - 0.5 * g.cell_size;
  for (int a = 0; a < 20; ++a)
    for (int b = 0; b < 20; ++b)
      k += in(lo + g.cell_size * NodeVector((a + 0.5) / 20.0, (b + 0.5) / 20.0));
  return k / 400.0;
}

struct ShapeResult {
  double mass_error, smeared_cells, shape_error, smallest, largest;
};

// Translates a shape by 20 cells in x and 10 in y at Courant 0.4 (x); returns the mass error,
// the smearing (cells with 0.01 < vf < 0.99 per cell of exact perimeter), the L1 shape error
// (sum |vf - exact| over the exact area) and the unclipped vf range.
ShapeResult translate(MaterialFlux flux, const std::function<bool(NodeVector)>& shape) {
  const double h = 0.01;
  Translation t(60, h, flux);
  for (std::size_t c = 0; c < t.grid.cell_count(); ++c) {
    const double vf = covered(t.grid, c, shape);
    t.cells.volume_fraction[c] = vf;
    t.cells.mass[c] = vf * t.grid.cell_volume(c) * 290.0;
    t.cells.stress[c] = -100.0 * Eigen::Matrix3d::Identity();
    t.cells.void_ratio[c] = 0.71;
  }
  double m0 = 0.0, exact_area = 0.0;
  for (std::size_t c = 0; c < t.grid.cell_count(); ++c) m0 += t.cells.mass[c];
  const NodeVector v(1.0, 0.5), shift = 20.0 * h * NodeVector(1.0, 0.5);
  t.run(v, 0.4 * h, 50);
  double m = 0.0, mixed = 0.0, error = 0.0, perimeter = 0.0;
  const auto moved = [&](NodeVector x) { return shape(x - shift); };
  for (std::size_t c = 0; c < t.grid.cell_count(); ++c) {
    const double vf = t.cells.volume_fraction[c], exact = covered(t.grid, c, moved);
    m += t.cells.mass[c];
    mixed += vf > 0.01 && vf < 0.99;
    perimeter += exact > 0.0 && exact < 1.0;
    error += std::abs(vf - exact);
    exact_area += exact;
  }
  return {(m + t.removed) / m0 - 1.0, mixed / perimeter, error / exact_area, t.smallest, t.largest};
}

void expect_sharper(const char* name, const std::function<bool(NodeVector)>& shape) {
  const ShapeResult donor = translate(MaterialFlux::donor_cell, shape);
  const ShapeResult plic = translate(MaterialFlux::plic, shape);
  const ShapeResult limited = translate(MaterialFlux::limited, shape);
  for (const auto& [label, r] : {std::pair{"donor cell", donor}, {"limited", limited}, {"PLIC", plic}})
    std::printf("%s, %s: mass %.2e, mixed cells per interface cell %.2f, L1 shape error %.3f, "
                "vf in [%.3g, %.15g]\n", name, label, r.mass_error, r.smeared_cells, r.shape_error,
                r.smallest, r.largest);
  EXPECT_LT(std::abs(plic.mass_error), 1e-13);
  EXPECT_LT(std::abs(limited.mass_error), 1e-13);
  EXPECT_LT(plic.shape_error, 0.5 * donor.shape_error);
  EXPECT_LT(plic.smeared_cells, 0.5 * donor.smeared_cells);
  EXPECT_LT(limited.shape_error, donor.shape_error);
  for (const ShapeResult& r : {donor, limited, plic}) {
    EXPECT_GE(r.smallest, -1e-15);
    EXPECT_LE(r.largest, 1.0 + 1e-12);
  }
}

// A 12 x 12 cell square, off the grid lines, keeps its edges sharp under PLIC.
TEST(PlicInterface, TranslatedSquareStaysSharp) {
  expect_sharper("square", [](NodeVector x) {
    return x.x() > 0.083 && x.x() < 0.203 && x.y() > 0.102 && x.y() < 0.222;
  });
}

// A disc of radius 7 cells keeps its shape under PLIC.
TEST(PlicInterface, TranslatedDiscKeepsItsShape) {
  expect_sharper("disc", [](NodeVector x) { return (x - NodeVector(0.15, 0.16)).norm() < 0.07; });
}

// A sliver of material beside a wall, with none around it, leaves the wall's row when it moves
// away along the wall (the 0.07-full cell under the lifted chute gate): PLIC with the wall's
// mirror put it in the cell's corner at the wall, away from the outflow face, and it never left.
TEST(PlicInterface, FragmentBesideAWallMovesAlongIt) {
  const double h = 0.01;
  Translation t(10, h, MaterialFlux::plic);
  for (int j = 5; j < 10; ++j) t.cells.solid[t.grid.cell(5, j)] = true;  // a plate from row 5 up
  const std::size_t sliver = t.grid.cell(4, 5);
  t.cells.volume_fraction[sliver] = 0.07;
  t.cells.mass[sliver] = 0.07 * t.grid.cell_volume(sliver) * 290.0;
  t.cells.stress[sliver] = -100.0 * Eigen::Matrix3d::Identity();
  t.cells.void_ratio[sliver] = 0.71;
  const double m0 = t.cells.mass[sliver];
  t.run(NodeVector(0.0, -1.0), 0.4 * h, 10);  // 4 cells down along the plate
  double m = 0.0, at_the_wall_row = 0.0, moment = 0.0;
  for (std::size_t c = 0; c < t.grid.cell_count(); ++c) {
    m += t.cells.mass[c];
    moment += t.cells.mass[c] * t.grid.cell_centre(c).y();
    if (t.grid.cell_j(c) >= 5) at_the_wall_row += t.cells.mass[c];
  }
  EXPECT_NEAR(m + t.removed, m0, 1e-12 * m0);
  EXPECT_LT(at_the_wall_row, 0.05 * m0);
  EXPECT_LT(moment / m, t.grid.cell_centre(sliver).y() - 2.0 * h);  // moved down (4 h exactly)
}

// A sliver right under a wall, with dust beside it, falls away from the wall (the 0.08-full
// cell under the lifted chute gate's lower face): the wall's mirror put it against the wall, above
// the slab leaving through the bottom face, and it stayed while its nodes fell to 44 m/s.
TEST(PlicInterface, FragmentUnderAWallFallsAwayFromIt) {
  const double h = 0.01;
  Translation t(10, h, MaterialFlux::plic);
  for (int j = 6; j < 10; ++j)
    for (int i = 3; i < 7; ++i) t.cells.solid[t.grid.cell(i, j)] = true;  // a plate above row 5
  const auto fill = [&](std::size_t c, double vf) {
    t.cells.volume_fraction[c] = vf;
    t.cells.mass[c] = vf * t.grid.cell_volume(c) * 290.0;
    t.cells.stress[c] = -100.0 * Eigen::Matrix3d::Identity();
    t.cells.void_ratio[c] = 0.71;
  };
  const std::size_t sliver = t.grid.cell(4, 5);
  fill(sliver, 0.083);
  fill(t.grid.cell(5, 5), 0.0004);  // dust: the sliver is not alone, so not a donor-cell fragment
  double m0 = 0.0;
  for (double m : t.cells.mass) m0 += m;
  t.run(NodeVector(0.0, -1.0), 0.4 * h, 10);  // 4 cells down, away from the plate
  double m = 0.0, under_the_wall = 0.0, moment = 0.0;
  for (std::size_t c = 0; c < t.grid.cell_count(); ++c) {
    m += t.cells.mass[c];
    moment += t.cells.mass[c] * t.grid.cell_centre(c).y();
    if (t.grid.cell_j(c) == 5) under_the_wall += t.cells.mass[c];
  }
  EXPECT_NEAR(m + t.removed, m0, 1e-12 * m0);
  EXPECT_LT(under_the_wall, 0.05 * m0);
  EXPECT_LT(moment / m, t.grid.cell_centre(sliver).y() - 2.0 * h);  // moved down (4 h exactly)
}

}  // namespace
}  // namespace feedflow::cel
