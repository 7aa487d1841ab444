// The Lagrangian phase on its own: patch tests of the one-point quadrilateral (models.md 2.3).
#include <gtest/gtest.h>


#include "fullsim/cel/cel_fields.hpp"
#include "fullsim/cel/lagrangian_phase.hpp"
#include "fullsim/cel/nodal_forces.hpp"
#include "fullsim/cel/quad_cell.hpp"

namespace feedflow::cel {
namespace {

struct Patch {
  CelGrid grid = make_plane_strain_grid(5, 4, 0.02);
  CellFields cells;
  NodeFields nodes;
  std::vector<std::size_t> active;
  Patch() {
    cells.resize(grid.cell_count());
    nodes.resize(grid.node_count());
    for (std::size_t c = 0; c < grid.cell_count(); ++c) {
      cells.volume_fraction[c] = 1.0;
      cells.mass[c] = 300.0 * grid.cell_volume(c);
      cells.wave_speed[c] = 40.0;
      active.push_back(c);
    }
    lump_nodal_mass(grid, cells, nodes);
  }
};

// A linear velocity field v = A x + b gives L = A in every element and no hourglass force.
TEST(CelLagrangianPatch, LinearVelocityUniformStrainRateNoHourglass) {
  Patch p;
  Eigen::Matrix2d a;
  a << 0.3, -1.1, 0.7, -0.4;
  const NodeVector b(0.5, -0.2);
  for (std::size_t n = 0; n < p.grid.node_count(); ++n)
    p.nodes.velocity[n] = a * p.grid.node_position(n) + b;
  for (std::size_t c : p.active) {
    CellVelocities v;
    const auto ids = p.grid.cell_nodes(c);
    for (int k = 0; k < kNodesPerCell; ++k) v[k] = p.nodes.velocity[ids[k]];
    EXPECT_LT((velocity_gradient(v, p.grid.cell_size).topLeftCorner<2, 2>() - a).norm(), 1e-12);
    EXPECT_LT(hourglass_velocity(v).norm(), 1e-12);
  }
  // Zero stress and no volume change: the assembled forces are hourglass forces only -> zero.
  ForceOptions o;
  o.linear_bulk_viscosity = 0.0;
  o.quadratic_bulk_viscosity = 0.0;
  assemble_nodal_forces(p.grid, p.active, o, NodeVector::Zero(), p.cells, p.nodes);
  for (const NodeVector& f : p.nodes.force) EXPECT_LT(f.norm(), 1e-12);
}

// The hourglass mode itself is resisted (the control acts), and opposes the motion.
TEST(CelLagrangianPatch, HourglassModeIsResisted) {
  Patch p;
  for (std::size_t n = 0; n < p.grid.node_count(); ++n) {
    const double s = ((p.grid.node_i(n) + p.grid.node_j(n)) % 2 == 0) ? 1.0 : -1.0;
    p.nodes.velocity[n] = NodeVector(0.01 * s, 0.0);
  }
  assemble_nodal_forces(p.grid, p.active, ForceOptions{}, NodeVector::Zero(), p.cells, p.nodes);
  const std::size_t inner = p.grid.node(2, 2);
  EXPECT_LT(p.nodes.force[inner].dot(p.nodes.velocity[inner]), -1e-6);
}

// A uniform stress field is in equilibrium: interior nodes feel no force, boundary nodes feel
// the traction T n h/2 per face.
TEST(CelLagrangianPatch, UniformStressInEquilibrium) {
  Patch p;
  Eigen::Matrix3d t;
  t << -2e3, 300.0, 0.0, 300.0, -1e3, 0.0, 0.0, 0.0, -1.2e3;
  for (auto& s : p.cells.stress) s = t;
  assemble_nodal_forces(p.grid, p.active, ForceOptions{}, NodeVector::Zero(), p.cells, p.nodes);
  EXPECT_LT(p.nodes.force[p.grid.node(2, 2)].norm(), 1e-9);
  // Right edge, middle node: two half faces with normal +x: f = T n h (the force the cell exerts
  // on the node is -V T b, the boundary traction the wall must supply is its negative).
  const NodeVector f = p.nodes.force[p.grid.node(5, 2)];
  EXPECT_NEAR(f.x(), -t(0, 0) * 0.02, 1e-9);
  EXPECT_NEAR(f.y(), -t(1, 0) * 0.02, 1e-9);
}

// The mixed-cell rules (models.md 2.3 item 7): equal strain rate hands the material the cell's
// rate; void first gives a half-filled cell's material no volume change while the cell grows or
// shrinks within its void (the shear kept), and when a nearly full cell shrinks by more than
// its void, the rate that makes the material fill the new cell volume exactly.
TEST(CelMixedCells, VoidTakesTheVolumeChangeFirst) {
  Eigen::Matrix3d d = Eigen::Matrix3d::Zero();
  d(0, 0) = 3.0;
  d(1, 1) = 1.0;
  d(0, 1) = d(1, 0) = 0.5;
  const double dt = 1e-3;
  EXPECT_TRUE(material_rate_of_deformation(d, 0.5, dt, MixedCellRule::equal_strain_rate) == d);
  EXPECT_TRUE(material_rate_of_deformation(d, 1.0, dt, MixedCellRule::void_first) == d);
  const Eigen::Matrix3d grow = material_rate_of_deformation(d, 0.5, dt, MixedCellRule::void_first);
  EXPECT_NEAR(grow(0, 0) + grow(1, 1), 0.0, 1e-12);
  EXPECT_NEAR(grow(0, 0) - grow(1, 1), 2.0, 1e-12);  // deviatoric part kept
  EXPECT_EQ(grow(0, 1), 0.5);
  const Eigen::Matrix3d slight = material_rate_of_deformation(-d, 0.5, dt, MixedCellRule::void_first);
  EXPECT_NEAR(slight(0, 0) + slight(1, 1), 0.0, 1e-12);  // -0.4 % of the cell: the void's
  const double vf = 0.999, shrink = -0.25 / dt;  // the cell loses 25 %, its void only 0.1 %
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  c(0, 0) = c(1, 1) = 0.5 * shrink;
  const Eigen::Matrix3d m = material_rate_of_deformation(c, vf, dt, MixedCellRule::void_first);
  // The material volume vf V (1 + tr D_m dt) equals the new cell volume V (1 + tr D dt).
  EXPECT_NEAR(vf * (1.0 + (m(0, 0) + m(1, 1)) * dt), 1.0 + shrink * dt, 1e-12);
}

// A speck of material (vf < kNearlyEmpty) in a cell at a wall's staircase is void first under
// the equal-strain-rate rule: squeezed by its cell it keeps its void ratio (no volume change of
// the material). A speck away from walls, and a fuller cell at the wall, take the cell's rate
// and compact.
TEST(CelMixedCells, SpeckAtAWallIsVoidFirst) {
  Patch p;
  p.cells.solid[p.grid.cell(0, 0)] = kSolidInsideWall;
  p.cells.mass[p.grid.cell(0, 0)] = p.cells.volume_fraction[p.grid.cell(0, 0)] = 0.0;
  const std::size_t wall_speck = p.grid.cell(1, 1), free_speck = p.grid.cell(3, 2), wall_full = p.grid.cell(1, 0);
  for (std::size_t c : {wall_speck, free_speck}) p.cells.volume_fraction[c] = 0.5 * kNearlyEmpty;
  for (std::size_t c = 0; c < p.grid.cell_count(); ++c) {
    p.cells.void_ratio[c] = 0.8;
    p.cells.stress[c] = -100.0 * Eigen::Matrix3d::Identity();
  }
  for (std::size_t a = 0; a < p.grid.node_count(); ++a)
    p.nodes.velocity[a] = -2.0 * p.grid.node_position(a);  // uniform compression, tr D = -4 /s
  std::vector<std::size_t> active;
  for (std::size_t c : p.active)
    if (!p.cells.solid[c]) active.push_back(c);
  update_cell_states(p.grid, active, make_hypoplastic_model(loblolly_pine_table1()), SubsteppingOptions{},
                     MixedCellRule::equal_strain_rate, 1e-4, p.nodes, p.cells);
  EXPECT_DOUBLE_EQ(p.cells.void_ratio[wall_speck], 0.8);
  EXPECT_NEAR(p.cells.void_ratio[free_speck], 0.8 - 1.8 * 4.0 * 1e-4, 1e-6);
  EXPECT_NEAR(p.cells.void_ratio[wall_full], 0.8 - 1.8 * 4.0 * 1e-4, 1e-6);
}

}  // namespace
}  // namespace feedflow::cel
