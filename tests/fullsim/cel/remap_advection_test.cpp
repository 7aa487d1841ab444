// The remap phase alone in a prescribed velocity field (no Lagrangian phase): second-order
// (van Leer MUSCL) advection of the cell state against first-order donor cell, conservation of
// every content for each remap variant, boundedness of the volume fraction (models.md 2.4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "fullsim/cel/nodal_forces.hpp"
#include "fullsim/cel/remap_phase.hpp"

namespace feedflow::cel {
namespace {

constexpr double kDensity = 290.0, kVoidRatio = 0.71;

// Cells and nodes of a closed grid (open box faces: no flux) whose nodes get the prescribed
// velocity before every remap.
struct PrescribedFlow {
  CelGrid grid;
  CellFields cells;
  NodeFields nodes;
  RemapPhase remap;
  std::function<NodeVector(const NodeVector&)> velocity;
  long steps = 0;
  RemapReport last{};

  PrescribedFlow(int nx, int ny, double h, const RemapOptions& options)
      : grid(make_plane_strain_grid(nx, ny, h)), remap(options, 0.0) {  // no cut: nothing removed
    cells.resize(grid.cell_count());
    nodes.resize(grid.node_count());
  }
  void fill(std::size_t c, double vf, const Eigen::Matrix3d& stress, double e = kVoidRatio) {
    cells.volume_fraction[c] = vf;
    cells.mass[c] = vf * grid.cell_volume(c) * kDensity;
    cells.stress[c] = stress;
    cells.void_ratio[c] = e;
  }
  void step(double dt) {
    for (std::size_t a = 0; a < grid.node_count(); ++a)
      nodes.velocity[a] = velocity(grid.node_position(a));
    const BoxWalls open{WallCondition::open, WallCondition::open, WallCondition::open,
                        WallCondition::open};
    last = remap.remap(grid, open, dt, steps % 2 == 0, 0.0, cells, nodes);
    ++steps;
  }
  double sum(const std::function<double(std::size_t)>& f) const {
    double s = 0.0;
    for (std::size_t c = 0; c < grid.cell_count(); ++c) s += f(c);
    return s;
  }
};

RemapOptions first_order() { return {}; }
RemapOptions second_order() { return second_order_state(); }

// A Gaussian stress bump (background -1 kPa, height 0.5 kPa, standard deviation `width`) in a
// full row of cells advected `distance` at Courant number 0.5; returns the L1 error of sigma_xx
// against the exact translated bump [Pa m] and the kept height share.
struct BumpResult {
  double l1_error, kept_height;
};
BumpResult advect_bump(const RemapOptions& options, double h, double width, double distance) {
  const double length = 0.8, x0 = 0.2, v = 1.0;
  const int nx = static_cast<int>(std::lround(length / h));
  PrescribedFlow flow(nx, 1, h, options);
  const auto bump = [&](double x) { return -1000.0 - 500.0 * std::exp(-0.5 * std::pow(x / width, 2)); };
  for (std::size_t c = 0; c < flow.grid.cell_count(); ++c)
    flow.fill(c, 1.0, bump(flow.grid.cell_centre(c).x() - x0) * Eigen::Matrix3d::Identity());
  flow.velocity = [&](const NodeVector&) { return NodeVector(v, 0.0); };
  const double dt = 0.5 * h / v;
  const int steps = static_cast<int>(std::lround(distance / (v * dt)));
  for (int k = 0; k < steps; ++k) flow.step(dt);
  double error = 0.0, lowest = 0.0;
  for (std::size_t c = 0; c < flow.grid.cell_count(); ++c) {
    const double s = flow.cells.stress[c](0, 0);
    error += h * std::abs(s - bump(flow.grid.cell_centre(c).x() - x0 - distance));
    lowest = std::min(lowest, s);
  }
  return {error, (-1000.0 - lowest) / 500.0};
}

// A bump of standard deviation 3 cells travelling 20 cells at Courant 0.5 keeps far more of its
// height at second order (measured 0.893) than with the donor cell (0.683): fails if the
// second-order path were first order.
TEST(CelRemapAdvection, SecondOrderKeepsAStressBump) {
  const double h = 0.01;
  const BumpResult first = advect_bump(first_order(), h, 3.0 * h, 20.0 * h);
  const BumpResult second = advect_bump(second_order(), h, 3.0 * h, 20.0 * h);
  std::printf("bump height kept after 20 cells: donor cell %.3f, MUSCL %.3f\n", first.kept_height,
              second.kept_height);
  RecordProperty("kept_height_first", std::to_string(first.kept_height));
  RecordProperty("kept_height_second", std::to_string(second.kept_height));
  EXPECT_LT(first.kept_height, 0.75);
  EXPECT_GT(second.kept_height, 0.85);
  EXPECT_LE(second.kept_height, 1.0 + 1e-12);  // no new extremum
}

// A row of full cells carried at u = 1 m/s (x velocity prescribed every step) whose nodes carry
// a Gaussian bump of the transverse velocity v_y (sd 3 cells, 0.1 m/s) as momentum: after 20
// cells at Courant 0.5 the donor-cell momentum keeps less of the bump than the MUSCL face
// velocities, which add no new extremum; the momentum is conserved to round-off either way.
TEST(CelRemapAdvection, SecondOrderMomentumKeepsAVelocityBump) {
  const auto carry = [](bool second) {
    const double h = 0.01, u = 1.0, width = 3.0 * h, x0 = 0.2;
    RemapOptions o;
    o.second_order_momentum = second;
    PrescribedFlow flow(80, 1, h, o);
    for (std::size_t c = 0; c < flow.grid.cell_count(); ++c)
      flow.fill(c, 1.0, -1000.0 * Eigen::Matrix3d::Identity());
    std::vector<double> vy(flow.grid.node_count());
    for (std::size_t a = 0; a < flow.grid.node_count(); ++a)
      vy[a] = 0.1 * std::exp(-0.5 * std::pow((flow.grid.node_position(a).x() - x0) / width, 2));
    const auto momentum = [&] {
      double p = 0.0;
      for (std::size_t a = 0; a < flow.grid.node_count(); ++a) p += flow.nodes.mass[a] * vy[a];
      return p;
    };
    lump_nodal_mass(flow.grid, flow.cells, flow.nodes);
    const double p0 = momentum();
    flow.velocity = [&](const NodeVector&) { return NodeVector(u, 0.0); };
    const double dt = 0.5 * h / u;
    for (int k = 0; k < 40; ++k) {
      for (std::size_t a = 0; a < flow.grid.node_count(); ++a)
        flow.nodes.velocity[a] = NodeVector(u, vy[a]);
      const BoxWalls open{WallCondition::open, WallCondition::open, WallCondition::open,
                          WallCondition::open};
      flow.remap.remap(flow.grid, open, dt, k % 2 == 0, 0.0, flow.cells, flow.nodes);
      for (std::size_t a = 0; a < flow.grid.node_count(); ++a) vy[a] = flow.nodes.velocity[a].y();
    }
    double top = 0.0;
    for (double v : vy) top = std::max(top, v);
    EXPECT_NEAR(momentum() / p0, 1.0, 1e-12);
    return top / 0.1;
  };
  const double first = carry(false), second = carry(true);
  std::printf("velocity bump kept after 20 cells: donor cell %.3f, MUSCL %.3f\n", first, second);
  EXPECT_LT(first, 0.75);
  EXPECT_GT(second, 0.85);
  EXPECT_LE(second, 1.0 + 1e-12);
}

// L1 error of a smooth bump (5 cm wide, carried 0.2 m) on 10, 5 and 2.5 mm cells: the observed
// order over the two halvings is about 1 for the donor cell (measured 0.9) and well above 1.5
// for the limited MUSCL (measured 1.76; van Leer clips the peak, so not quite 2).
TEST(CelRemapAdvection, ObservedOrderOfAccuracy) {
  const auto order = [](const RemapOptions& o) {
    const double e1 = advect_bump(o, 0.01, 0.05, 0.2).l1_error;
    const double e2 = advect_bump(o, 0.005, 0.05, 0.2).l1_error;
    const double e3 = advect_bump(o, 0.0025, 0.05, 0.2).l1_error;
    std::printf("L1 errors %.4g %.4g %.4g Pa m\n", e1, e2, e3);
    return 0.5 * std::log2(e1 / e3);
  };
  const double first = order(first_order()), second = order(second_order());
  std::printf("observed order: donor cell %.2f, MUSCL %.2f\n", first, second);
  EXPECT_LT(first, 1.2);
  EXPECT_GT(second, 1.5);
}

// A linear stress and void-ratio field is translated exactly (to round-off, 1e-12 relative) in
// the interior: the limiter keeps the exact slope. (The donor cell is exact on a line too: the
// bump and order tests are the ones that tell the orders apart.)
TEST(CelRemapAdvection, LinearFieldIsTranslatedExactly) {
  const double h = 0.01, v = 1.0, dt = 0.3 * h / v;
  PrescribedFlow flow(120, 1, h, second_order());
  const auto line = [](double x) { return -1000.0 - 2000.0 * x; };
  for (std::size_t c = 0; c < flow.grid.cell_count(); ++c)
    flow.fill(c, 1.0, line(flow.grid.cell_centre(c).x()) * Eigen::Matrix3d::Identity(),
              0.5 + flow.grid.cell_centre(c).x());
  flow.velocity = [&](const NodeVector&) { return NodeVector(v, 0.0); };
  for (int k = 0; k < 30; ++k) flow.step(dt);
  double worst = 0.0, worst_e = 0.0;
  for (int i = 30; i < 60; ++i) {
    const double x = flow.grid.cell_centre(flow.grid.cell(i, 0)).x() - 30 * v * dt;
    worst = std::max(worst, std::abs(flow.cells.stress[flow.grid.cell(i, 0)](0, 0) - line(x)));
    worst_e = std::max(worst_e, std::abs(flow.cells.void_ratio[flow.grid.cell(i, 0)] - 0.5 - x));
  }
  EXPECT_LT(worst, 1e-8);  // of about 2 kPa
  EXPECT_LT(worst_e, 1e-12);
}

// Every remap variant conserves mass, void mass (e M) and the stress integral (T vf V) to
// round-off in a rotating flow inside a closed box, and keeps 0 <= vf <= 1 without clipping.
class CelRemapVariants : public ::testing::TestWithParam<int> {};

RemapOptions variant(int k) {
  RemapOptions o = k % 2 == 0 ? first_order() : second_order();
  o.material_flux = k / 2 == 0 ? MaterialFlux::donor_cell
                    : k / 2 == 1 ? MaterialFlux::limited
                                 : MaterialFlux::plic;
  return o;
}

TEST_P(CelRemapVariants, ConserveContentsInARotatingFlow) {
  const double h = 0.01, omega = 2.0;
  // Wide box: the rotation is discretely divergence free except in the cells along the box
  // faces (no flux there), which the material's donor-cell tail must not reach.
  PrescribedFlow flow(100, 100, h, variant(GetParam()));
  const NodeVector centre(0.5, 0.5);
  for (std::size_t c = 0; c < flow.grid.cell_count(); ++c) {
    const NodeVector x = flow.grid.cell_centre(c);
    if (x.x() < 0.42 || x.x() > 0.6 || x.y() < 0.38 || x.y() > 0.52) continue;
    const double vf = (x.x() < 0.425 || x.y() > 0.515) ? 0.5 : 1.0;
    flow.fill(c, vf, (-500.0 - 4000.0 * x.y() + 300.0 * std::sin(40.0 * x.x())) *
                         Eigen::Matrix3d::Identity(), 0.6 + x.x());
  }
  flow.velocity = [&](const NodeVector& x) { return NodeVector(-omega * (x.y() - centre.y()), omega * (x.x() - centre.x())); };
  const auto mass = [&](std::size_t c) { return flow.cells.mass[c]; };
  const auto void_mass = [&](std::size_t c) { return flow.cells.void_ratio[c] * flow.cells.mass[c]; };
  const auto stress = [&](std::size_t c) {
    return flow.cells.stress[c](0, 0) * flow.cells.volume_fraction[c] * flow.grid.cell_volume(c);
  };
  const double m0 = flow.sum(mass), e0 = flow.sum(void_mass), s0 = flow.sum(stress);
  const double dt = 0.4 * h / (omega * 0.71);
  double largest = 0.0, smallest = 1.0, removed = 0.0;
  for (int k = 0; k < 200; ++k) {
    flow.step(dt);
    largest = std::max(largest, flow.last.largest_volume_fraction);
    smallest = std::min(smallest, flow.last.smallest_volume_fraction);
    removed += flow.last.removed_mass;  // round-off specks below the cut
  }
  std::printf("variant %d: mass %.2e, void mass %.2e, stress %.2e; vf in [%.3g, %.15g]\n",
              GetParam(), (flow.sum(mass) + removed) / m0 - 1.0, flow.sum(void_mass) / e0 - 1.0,
              flow.sum(stress) / s0 - 1.0, smallest, largest);
  EXPECT_NEAR((flow.sum(mass) + removed) / m0, 1.0, 1e-13);
  EXPECT_LT(removed / m0, 1e-12);
  EXPECT_NEAR(flow.sum(void_mass) / e0, 1.0, 1e-13);
  EXPECT_NEAR(flow.sum(stress) / s0, 1.0, 1e-12);
  EXPECT_LE(largest, 1.0 + 1e-12);
  EXPECT_GE(smallest, -1e-15);
}

// Variants 0..5: {first, second} order state x {donor cell, limited, PLIC} material flux.
INSTANTIATE_TEST_SUITE_P(AllRemaps, CelRemapVariants, ::testing::Range(0, 6));

}  // namespace
}  // namespace feedflow::cel
