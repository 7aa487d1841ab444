// The axisymmetric (r, z) grid's element and remap (issue 22): hoop terms, r-weighted volumes.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "fullsim/cel/cel_solver.hpp"
#include "fullsim/cel/nodal_forces.hpp"
#include "fullsim/cel/quad_cell.hpp"
#include "fullsim/cel/remap_phase.hpp"

namespace feedflow::cel {
namespace {

constexpr double kCell = 0.01;

// A grid on the axis filled with material of density 300 kg/m^3 at stress `t`.
struct FilledGrid {
  CelGrid grid;
  CellFields cells;
  NodeFields nodes;
  std::vector<std::size_t> active;
  FilledGrid(int nr, int nz, const Eigen::Matrix3d& t, double r0 = 0.0)
      : grid(make_axisymmetric_grid(nr, nz, kCell, {r0, 0.0})) {
    cells.resize(grid.cell_count());
    nodes.resize(grid.node_count());
    for (std::size_t c = 0; c < grid.cell_count(); ++c) {
      cells.volume_fraction[c] = 1.0;
      cells.mass[c] = 300.0 * grid.cell_volume(c);
      cells.stress[c] = t;
      cells.void_ratio[c] = 0.7;
      cells.wave_speed[c] = 50.0;
      active.push_back(c);
    }
    lump_nodal_mass(grid, cells, nodes);
  }
};

// A cell's volume is the r-weighted area h^2 r_c: the grid on the axis holds pi R^2 H / (2 pi).
TEST(AxisymmetricCell, VolumesSumToTheCylinder) {
  const CelGrid g = make_axisymmetric_grid(7, 3, kCell);
  double v = 0.0;
  for (std::size_t c = 0; c < g.cell_count(); ++c) v += g.cell_volume(c);
  const double r = 7 * kCell, height = 3 * kCell;
  EXPECT_NEAR(v * revolution_factor(g) / (M_PI * r * r * height), 1.0, 1e-14);
  EXPECT_THROW(make_axisymmetric_grid(2, 2, kCell, {-0.1, 0.0}), std::invalid_argument);
}

// A uniform stress with T_rr = T_thth is in equilibrium (div T = 0 in cylindrical coordinates):
// the hoop share cancels the radial imbalance of the r-weighted volumes at every node, on the
// axis and at the interior nodes, to round-off; with the hoop term left out it would not.
TEST(AxisymmetricCell, UniformStressIsInEquilibriumAtEveryInnerNode) {
  Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
  t.diagonal() << -2000.0, -5000.0, -2000.0;
  FilledGrid f(6, 5, t);
  assemble_nodal_forces(f.grid, f.active, ForceOptions{}, NodeVector::Zero(), f.cells, f.nodes);
  const double scale = 5000.0 * kCell * kCell * 6 * kCell;  // |T| h times the largest radius
  for (std::size_t a = 0; a < f.grid.node_count(); ++a) {
    const int i = f.grid.node_i(a), j = f.grid.node_j(a);
    if (i == f.grid.nx || j == 0 || j == f.grid.ny) continue;  // the free outer faces
    EXPECT_LT(f.nodes.force[a].norm(), 1e-12 * scale) << "node (" << i << ", " << j << ")";
  }
}

// v_r = eps r, v_z = 0 is a uniform radial stretch: every cell's rate of deformation is
// diag(eps, 0, eps) exactly (the hoop rate of the corner mean equals the centre's).
TEST(AxisymmetricCell, RadialStretchHasHoopRateEqualToRadialRate) {
  const CelGrid g = make_axisymmetric_grid(5, 2, kCell, {0.3, 0.0});
  const double eps = 0.7;
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    CellVelocities v;
    const auto nodes = g.cell_nodes(c);
    for (int a = 0; a < kNodesPerCell; ++a) v[a] = NodeVector(eps * g.node_position(nodes[a]).x(), 0.0);
    const Eigen::Matrix3d l = velocity_gradient(v, g.cell_size, g.inverse_radius(c));
    EXPECT_NEAR(l(0, 0), eps, 1e-12);
    EXPECT_NEAR(l(2, 2), eps, 1e-12);
    EXPECT_NEAR(l(1, 1), 0.0, 1e-12);
  }
}

// The r-weighted integral over cell c of f(r, z), by 2 x 2 Gauss points (exact for the bilinear
// velocity times r, and for the bilinear shape functions' gradients times r).
template <class F>
double r_weighted_integral(const CelGrid& g, std::size_t c, F f) {
  const Eigen::Vector2d centre = g.cell_centre(c);
  const double offset = 0.5 * g.cell_size / std::sqrt(3.0),
               weight = 0.25 * g.cell_size * g.cell_size;
  double sum = 0.0;
  for (double sr : {-1.0, 1.0})
    for (double sz : {-1.0, 1.0}) {
      const double r = centre.x() + sr * offset, z = centre.y() + sz * offset;
      sum += weight * r * f(r, z);
    }
  return sum;
}

// The one-point hoop rate mean(v_r) / r_c is the cell's r-weighted mean of v_r / r for any
// bilinear velocity, so a selective or two-point radial quadrature of the hoop term would give
// the same rate; in the cell beside the axis too.
TEST(AxisymmetricCell, HoopRateIsTheCellsVolumeMeanOfTheBilinearField) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const CelGrid g = make_axisymmetric_grid(6, 2, kCell);
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    CellVelocities v;
    for (auto& x : v) x = NodeVector(u(rng), u(rng));
    const Eigen::Vector2d lower_left = g.cell_centre(c) - Eigen::Vector2d::Constant(0.5 * kCell);
    auto radial_velocity = [&](double r, double z) {  // the bilinear interpolant of the corners
      const double s = (r - lower_left.x()) / kCell, t = (z - lower_left.y()) / kCell;
      return (1 - s) * (1 - t) * v[0].x() + s * (1 - t) * v[1].x() + s * t * v[2].x() +
             (1 - s) * t * v[3].x();
    };
    const double mean_hoop_rate =
        r_weighted_integral(g, c, [&](double r, double z) { return radial_velocity(r, z) / r; }) /
        g.cell_volume(c);
    EXPECT_NEAR(velocity_gradient(v, g.cell_size, g.inverse_radius(c))(2, 2), mean_hoop_rate,
                1e-12 * std::abs(mean_hoop_rate) + 1e-12);
  }
}

// The incompressible sink flow v_r = -A / r, v_z = 0 converges around the hoop while it
// stretches radially: every cell's rate of deformation is traceless to round-off, so the element
// compacts nothing that converges without a change of volume (the remap's face fluxes agree:
// SourceFlowKeepsTheCellsFull).
TEST(AxisymmetricCell, IsochoricSinkFlowHasNoVolumeRate) {
  const CelGrid g = make_axisymmetric_grid(12, 2, kCell, {0.005, 0.0});
  const double a = 0.03;  // [m^2/s]
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    CellVelocities v;
    const auto nodes = g.cell_nodes(c);
    for (int k = 0; k < kNodesPerCell; ++k)
      v[k] = NodeVector(-a / g.node_position(nodes[k]).x(), 0.0);
    const Eigen::Matrix3d l = velocity_gradient(v, g.cell_size, g.inverse_radius(c));
    EXPECT_LT(l(2, 2), 0.0);  // the hoop converges
    EXPECT_NEAR(l.trace(), 0.0, 1e-12 * std::abs(l(2, 2))) << "column " << g.cell_i(c);
  }
}

// The one-point in-plane forces -V T b_a differ from the r-weighted integral of T grad N_a over
// the cell only in the part of dN_a/dz, which varies with r inside the cell: by |T e_z| h^2 / 12
// on a share |T e_z| h r_c / 2, a relative h / (6 r_c). That is 0.4 % for 2.5 mm cells at
// r = 0.1 m, so a full quadrature would not move a wall band there.
TEST(AxisymmetricCell, OnePointInPlaneForcesDifferFromTheFullQuadratureByHOverSixR) {
  Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
  t(0, 0) = -800.0, t(1, 1) = -1500.0, t(0, 1) = t(1, 0) = 400.0;
  const double column_z = t.topLeftCorner<2, 2>().col(1).norm();
  const CelGrid g = make_axisymmetric_grid(8, 1, kCell);
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    const auto one_point = stress_nodal_forces(t, g.cell_volume(c), g.cell_size);  // in-plane only
    const Eigen::Vector2d lower_left = g.cell_centre(c) - Eigen::Vector2d::Constant(0.5 * kCell);
    for (int k = 0; k < kNodesPerCell; ++k) {
      auto shape_gradient = [&](double r, double z) {  // grad N_k of the bilinear element
        const double s = (r - lower_left.x()) / kCell, tz = (z - lower_left.y()) / kCell;
        const double ws = kXi[k] > 0 ? s : 1 - s, wt = kEta[k] > 0 ? tz : 1 - tz;
        return std::array<double, 2>{kXi[k] * wt / kCell, kEta[k] * ws / kCell};
      };
      Eigen::Vector2d exact = Eigen::Vector2d::Zero();
      for (int i = 0; i < 2; ++i)
        exact[i] = -r_weighted_integral(g, c, [&](double r, double z) {
          const auto b = shape_gradient(r, z);
          return t(i, 0) * b[0] + t(i, 1) * b[1];
        });
      EXPECT_NEAR((exact - one_point[k]).norm(), column_z * kCell * kCell / 12.0,
                  1e-12 * column_z * kCell * kCell)
          << "column " << g.cell_i(c) << ", node " << k;
    }
  }
}

// The nodal forces are the virtual power of the stress: sum_a f_a . v_a = -V T : D for any
// corner velocities, hoop terms included (the element is energy consistent).
TEST(AxisymmetricCell, NodalForcesAreTheStressPower) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const CelGrid g = make_axisymmetric_grid(4, 1, kCell);
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
    t(0, 0) = 1000 * u(rng), t(1, 1) = 1000 * u(rng), t(2, 2) = 1000 * u(rng);
    t(0, 1) = t(1, 0) = 1000 * u(rng);
    CellVelocities v;
    for (auto& x : v) x = NodeVector(u(rng), u(rng));
    const double volume = g.cell_volume(c);
    const auto f = stress_nodal_forces(t, volume, g.cell_size, g.inverse_radius(c));
    const Eigen::Matrix3d l = velocity_gradient(v, g.cell_size, g.inverse_radius(c));
    double power = 0.0;
    for (int a = 0; a < kNodesPerCell; ++a) power += f[a].dot(v[a]);
    const Eigen::Matrix3d d = 0.5 * (l + l.transpose());
    EXPECT_NEAR(power, -volume * (t.cwiseProduct(d)).sum(), 1e-12 * 1000 * volume / kCell);
  }
}

// The incompressible source flow v_r = q / r carries the same volume through every face
// (face area h r_f): a full grid stays full to round-off under the remap. Without the
// r-weighted face areas the inner cells would lose 1 / r_c of their volume per unit time.
TEST(AxisymmetricRemap, SourceFlowKeepsTheCellsFull) {
  FilledGrid f(8, 3, -10.0 * Eigen::Matrix3d::Identity(), 0.05);
  const double q = 0.02;  // [m^2/s]
  for (std::size_t a = 0; a < f.grid.node_count(); ++a)
    f.nodes.velocity[a] = NodeVector(q / f.grid.node_position(a).x(), 0.0);
  RemapPhase remap;
  const BoxWalls open{WallCondition::outflow, WallCondition::outflow, WallCondition::free_slip,
                      WallCondition::free_slip};
  // Inflow through the inner face brings void only, so the first column thins; every other
  // column keeps volume fraction 1 (within round-off of the flux sums).
  remap.remap(f.grid, open, 1e-3, true, 0.0, f.cells, f.nodes);
  for (std::size_t c = 0; c < f.grid.cell_count(); ++c) {
    const int i = f.grid.cell_i(c);
    if (i == 0) continue;
    EXPECT_NEAR(f.cells.volume_fraction[c], 1.0, 1e-13) << "column " << i;
  }
}

// Remapping random velocities on an axisymmetric grid with closed faces keeps the mass and
// the material volume to round-off (every r-weighted flux leaves one cell and enters another).
TEST(AxisymmetricRemap, MassConservedToRoundOff) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  FilledGrid f(10, 10, -100.0 * Eigen::Matrix3d::Identity());
  for (std::size_t c = 0; c < f.grid.cell_count(); ++c)
    if (f.grid.cell_j(c) > 6 || f.grid.cell_i(c) > 7) {
      f.cells.volume_fraction[c] = 0.0;
      f.cells.mass[c] = 0.0;
    }
  lump_nodal_mass(f.grid, f.cells, f.nodes);
  auto total = [&] {
    double m = 0.0;
    for (double x : f.cells.mass) m += x;
    return m;
  };
  const double m0 = total();
  RemapPhase remap;
  const BoxWalls closed{WallCondition::free_slip, WallCondition::free_slip, WallCondition::free_slip,
                        WallCondition::free_slip};
  for (int step = 0; step < 20; ++step) {
    for (std::size_t a = 0; a < f.grid.node_count(); ++a) f.nodes.velocity[a] = NodeVector(u(rng), u(rng));
    apply_node_constraints(f.nodes);
    const RemapReport r = remap.remap(f.grid, closed, 2e-3, step % 2 == 0, 0.0, f.cells, f.nodes);
    EXPECT_EQ(r.outflow_mass, 0.0);
    EXPECT_EQ(r.removed_mass, 0.0);
  }
  EXPECT_NEAR(total() / m0, 1.0, 1e-13);
}

// The axis must be a symmetry line: any other condition on the face at r = 0 is refused.
TEST(AxisymmetricCell, AxisFaceMustBeFreeSlip) {
  CelOptions o;
  o.walls.left = WallCondition::no_slip;
  EXPECT_THROW(CelSolver(make_axisymmetric_grid(3, 3, kCell), make_hypoplastic_model(loblolly_pine_table1()), o),
               std::invalid_argument);
  o.walls.left = WallCondition::free_slip;
  EXPECT_NO_THROW(CelSolver(make_axisymmetric_grid(3, 3, kCell), make_hypoplastic_model(loblolly_pine_table1()), o));
}

}  // namespace
}  // namespace feedflow::cel
