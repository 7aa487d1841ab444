// Rigid walls at an angle to the grid with Coulomb friction (models.md 2.6, option C1): signed
// distance geometry, a pine block sliding on (or resting on) an inclined wall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "fullsim/cel/cel_solver.hpp"
#include "fullsim/cel/wall_contact.hpp"

namespace feedflow::cel {
namespace {

constexpr double kGravity = 9.81, kCell = 0.01;
const double kPineOnSteel = std::tan(8.5 * std::numbers::pi / 180.0);

// The signed distance of a two-segment polyline (a kinked hopper wall): positive on the material
// side (left of travel), exact to the segments, to the kink and along the end rays.
TEST(CelRigidWall, SignedDistanceOfKinkedPolyline) {
  RigidWall w;
  w.points = {{0.0, 1.0}, {0.0, 0.0}, {1.0, 0.0}};  // down, then right: material above-right
  const PlacedWall p(w, 0.0);
  NodeVector n;
  EXPECT_NEAR(p.signed_distance({0.5, 0.2}, &n), 0.2, 1e-15);
  EXPECT_NEAR(n.y(), 1.0, 1e-15);
  EXPECT_NEAR(p.signed_distance({0.3, 0.7}), 0.3, 1e-15);
  EXPECT_NEAR(p.signed_distance({-0.3, -0.4}), -0.5, 1e-15);  // behind the kink
  EXPECT_NEAR(p.signed_distance({5.0, -2.0}), -2.0, 1e-15);   // beyond the end: ray
  EXPECT_NEAR(p.signed_distance({-1.0, 7.0}), -1.0, 1e-15);
  // Moving: translated by v t and turned about the centre.
  w.velocity = {0.0, 1.0};
  w.angular_velocity = std::numbers::pi / 2.0;  // a quarter turn in 1 s
  const PlacedWall q(w, 1.0);  // now the points are (-1, 1), (0, 1), (0, 2)
  EXPECT_NEAR(q.signed_distance({-0.5, 0.8}), -0.2, 1e-12);
  EXPECT_NEAR(q.velocity_at({1.0, 1.0}).y(), 1.0 + std::numbers::pi / 2.0, 1e-12);
  // A removed wall is not placed.
  w.removal_time = 0.5;
  EXPECT_EQ(place_walls({w}, 0.4).size(), 1u);
  EXPECT_EQ(place_walls({w}, 0.5).size(), 0u);
}

// A pine slab, 0.4 m long and 35 mm thick (columns 20 mm wide, so only its ends slump), on a
// wall inclined at theta (not grid-aligned) through (0, 0.05); gravity at once, no damping.
struct InclinedBlock {
  double theta, mu;
  NodeVector tangent, normal;
  CelSolver solver;
  double mass0 = 0.0;
  InclinedBlock(double theta_deg, double friction, WallCells wall_cells = WallCells::staircase)
      : theta(theta_deg * std::numbers::pi / 180.0),
        mu(friction),
        tangent(std::cos(theta), std::sin(theta)),
        normal(-std::sin(theta), std::cos(theta)),
        solver(make_plane_strain_grid(60, 40, kCell),
               make_hypoplastic_model(loblolly_pine_table1()),
               options(theta, friction, wall_cells)) {
    for (int k = 0; k < 20; ++k) {
      const double x = 0.15 + 0.02 * k, top = 0.05 + (x + 0.01) * std::tan(theta) + 0.035;
      solver.add_material({{x, 0.0}, {x + 0.02, top}, 290.0, 0.7102, -10.0 * Eigen::Matrix3d::Identity()});
    }
    mass0 = solver.total_mass();
  }
  static CelOptions options(double theta, double friction, WallCells wall_cells) {
    CelOptions o;
    o.wall_cells = wall_cells;
    o.walls = {WallCondition::open, WallCondition::open, WallCondition::open, WallCondition::open};
    RigidWall w;
    w.points = {{0.0, 0.05}, {std::cos(theta), 0.05 + std::sin(theta)}};
    w.friction = friction;
    o.rigid_walls = {w};
    return o;
  }
  double speed_along() const { return solver.total_momentum().dot(tangent) / solver.total_mass(); }
  double speed_normal() const { return solver.total_momentum().dot(normal) / solver.total_mass(); }
  double height() const {  // centre of mass above the wall
    return PlacedWall(solver.options().rigid_walls[0], 0.0).signed_distance(solver.centre_of_mass());
  }
  // Mean acceleration down the slope between t1 and t2 [m/s^2].
  double acceleration(double t1, double t2) {
    solver.run_until(t1);
    const double u1 = speed_along(), s1 = solver.time();
    solver.run_until(t2);
    return -(speed_along() - u1) / (solver.time() - s1);
  }
};

// Sliding at 25 deg on pine-on-steel friction (mu = tan 8.5 deg): the mean acceleration between
// 0.1 s and 0.3 s is g (sin theta - mu cos theta) = 2.82 m/s^2 within 5 %.
TEST(CelInclinedWall, CoulombSlidingAcceleration) {
  InclinedBlock b(25.0, kPineOnSteel);
  const double a = b.acceleration(0.1, 0.3);
  const double expected = kGravity * (std::sin(b.theta) - b.mu * std::cos(b.theta));
  std::printf("a = %.3f m/s^2, g (sin - mu cos) = %.3f (%.2f %%)\n", a, expected,
              100.0 * (a / expected - 1.0));
  EXPECT_NEAR(a / expected, 1.0, 0.05);
  EXPECT_NEAR((b.solver.total_mass() + b.solver.removed_mass()) / b.mass0, 1.0, 1e-12);
}

// Cut cells carry the slab along the wall through their open faces, their nodes held by the
// wall: sliding at 25 deg on pine-on-steel the mean acceleration over 0.1-0.2 s is
// g (sin theta - mu cos theta) within 5 %, and mass is conserved to round-off.
TEST(CelInclinedWall, CutCellsSlideAtTheCoulombAcceleration) {
  InclinedBlock b(25.0, kPineOnSteel, WallCells::cut);
  const double a = b.acceleration(0.1, 0.2);
  const double expected = kGravity * (std::sin(b.theta) - b.mu * std::cos(b.theta));
  std::printf("cut cells: a = %.3f m/s^2 (%.2f %%), excess %.3f %% of the mass\n", a,
              100.0 * (a / expected - 1.0),
              100.0 * b.solver.overfilled_mass() / b.solver.total_mass());
  EXPECT_NEAR(a / expected, 1.0, 0.05);
  EXPECT_NEAR((b.solver.total_mass() + b.solver.removed_mass()) / b.mass0, 1.0, 1e-12);
}

// Frictionless at 30 deg: acceleration g sin theta within 5 %; no penetration: at the contact
// nodes (closer than h/2) the mass-weighted velocity into the wall, after the remap of every
// step, stays below 1e-3 of the sliding speed, cells inside the wall stay empty and the centre of
// mass stays above the wall.
TEST(CelInclinedWall, FrictionlessNoPenetration) {
  InclinedBlock b(30.0, 0.0);
  const PlacedWall wall(b.solver.options().rigid_walls[0], 0.0);
  const auto& g = b.solver.grid();
  b.solver.run_until(0.02);
  double worst_inward = 0.0, lowest = b.height(), in_solid = 0.0;
  const double t1 = b.solver.time(), u1 = b.speed_along();
  while (b.solver.time() < 0.25) {
    b.solver.step();
    double inward = 0.0, m = 0.0;
    for (std::size_t a = 0; a < g.node_count(); ++a) {
      NodeVector n;
      if (b.solver.nodes().mass[a] <= 0.0 || wall.signed_distance(g.node_position(a), &n) >= 0.5 * kCell)
        continue;
      inward += b.solver.nodes().mass[a] * std::max(0.0, -b.solver.nodes().velocity[a].dot(n));
      m += b.solver.nodes().mass[a];
    }
    worst_inward = std::max(worst_inward, inward / m / std::abs(b.speed_along()));
    lowest = std::min(lowest, b.height());
    for (std::size_t c = 0; c < g.cell_count(); ++c)
      if (b.solver.cells().solid[c]) in_solid += b.solver.cells().mass[c];
  }
  const double a = -(b.speed_along() - u1) / (b.solver.time() - t1);
  std::printf("a = %.3f m/s^2 (g sin = %.3f), inward contact speed / sliding speed %.3g, "
              "lowest centre of mass %.4f m\n", a, kGravity * std::sin(b.theta), worst_inward, lowest);
  EXPECT_NEAR(a / (kGravity * std::sin(b.theta)), 1.0, 0.05);
  EXPECT_LT(worst_inward, 1e-3);
  EXPECT_EQ(in_solid, 0.0);
  EXPECT_GT(lowest, 0.01);
}

// At 5 deg, below the friction angle 8.5 deg, the slab stays at rest: after 0.3 s its speed is
// below 1 % of the frictionless g sin theta t (0.26 m/s) and it moved less than 1 mm; the wall
// reaction averaged over 0.2-0.3 s carries the weight (0, M g) within 1 % of M g, including the
// friction force M g sin theta along the wall.
TEST(CelInclinedWall, StaysAtRestBelowFrictionAngle) {
  InclinedBlock b(5.0, kPineOnSteel);
  const NodeVector start = b.solver.centre_of_mass();
  b.solver.run_until(0.2);
  NodeVector impulse = NodeVector::Zero();
  const double t1 = b.solver.time();
  while (b.solver.time() < 0.3) {
    const CelStepReport r = b.solver.step();
    impulse += r.dt * r.wall_forces.at(0);
  }
  const NodeVector reaction = impulse / (b.solver.time() - t1);
  const double weight = b.solver.total_mass() * kGravity;
  const double moved = (b.solver.centre_of_mass() - start).dot(b.tangent);
  std::printf("speed along %.3g m/s, moved %.3g m, wall reaction / weight (%.4f, %.4f), along "
              "the wall %.4f (sin theta %.4f)\n", b.speed_along(), moved, reaction.x() / weight,
              reaction.y() / weight, reaction.dot(b.tangent) / weight, std::sin(b.theta));
  EXPECT_LT(std::abs(b.speed_along()), 0.01 * kGravity * std::sin(b.theta) * 0.3);
  EXPECT_LT(std::abs(moved), 1e-3);
  EXPECT_LT((reaction - NodeVector(0.0, weight)).norm(), 0.01 * weight);
}

// A moving wall: a no-slip belt inclined at 10 deg running up its own line at 0.2 m/s (the wall
// translates) carries the slab with it: after 0.2 s its mean velocity along the belt is 0.2 m/s
// within 2 %.
TEST(CelInclinedWall, MovingNoSlipBeltCarriesSlab) {
  InclinedBlock b(10.0, 0.0);
  CelOptions o = b.solver.options();
  o.rigid_walls[0].no_slip = true;
  o.rigid_walls[0].velocity = 0.2 * b.tangent;
  CelSolver s(b.solver.grid(), make_hypoplastic_model(loblolly_pine_table1()), o);
  for (int k = 0; k < 20; ++k) {
    const double x = 0.15 + 0.02 * k, top = 0.05 + (x + 0.01) * std::tan(b.theta) + 0.035;
    s.add_material({{x, 0.0}, {x + 0.02, top}, 290.0, 0.7102, -10.0 * Eigen::Matrix3d::Identity()});
  }
  s.run_until(0.2);
  const double u = s.total_momentum().dot(b.tangent) / s.total_mass();
  std::printf("slab speed along the belt %.4f m/s (belt 0.2)\n", u);
  EXPECT_NEAR(u / 0.2, 1.0, 0.02);
}

// The staircase of an inclined wall is the cell centres': an empty cell whose centre lies
// inside the wall is solid even with corners outside (a sliver takes no material, nor does a
// cut cell mostly inside), one whose centre is outside stays open, and a cell holding material
// is never solid.
TEST(CelRigidWall, WallCellsAreThoseWithTheirCentreInside) {
  const CelGrid g = make_plane_strain_grid(4, 4, kCell);
  // Material above the line y = 0.5 x + 0.009 (normal (-0.5, 1) / |.|).
  const RigidWall wall = make_half_plane_wall({0.0, 0.009}, NodeVector(-0.5, 1.0).normalized());
  const std::vector<PlacedWall> walls = {PlacedWall(wall, 0.0)};
  CellFields cells;
  cells.resize(g.cell_count());
  cells.mass[g.cell(0, 0)] = 1.0;  // holds material although its centre is deep inside
  mark_wall_cells(g, walls, cells);
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    const double d = distance_to_walls(walls, g.cell_centre(c));
    const bool expected = d <= 0.0 && cells.mass[c] <= 0.0;
    EXPECT_EQ(cells.solid[c] != 0, expected) << "cell " << g.cell_i(c) << ", " << g.cell_j(c) << " d " << d;
  }
  // Cell (1, 1): its centre (15, 15 mm) only 1.3 mm inside (the line is at 16.5 mm there), two
  // corners outside: solid.
  const double shallow = distance_to_walls(walls, g.cell_centre(g.cell(1, 1)));
  EXPECT_LT(shallow, 0.0);
  EXPECT_GT(shallow, -0.25 * kCell);
  EXPECT_GT(distance_to_walls(walls, {0.01, 0.02}), 0.0);
  EXPECT_EQ(cells.solid[g.cell(1, 1)], kSolidInsideWall);
  // Cell (2, 2): its centre (25, 25) 3.1 mm outside (line at 21.5), its corner (30, 20) inside: open.
  EXPECT_GT(distance_to_walls(walls, g.cell_centre(g.cell(2, 2))), 0.0);
  EXPECT_LT(distance_to_walls(walls, {0.03, 0.02}), 0.0);
  EXPECT_EQ(cells.solid[g.cell(2, 2)], 0);
  EXPECT_EQ(cells.solid[g.cell(0, 0)], 0);
}

// A wall face through a column of cell centres leaves that column open (half of each cell is
// free, and material there must slide along the face) and walls in the column behind it. Marked,
// the empty cells along the chute gate's face (through the centres of 20 mm cells) walled in the
// full one between them, and its nodes fell along the gate until the run blew up.
TEST(CelRigidWall, ACentreOnAWallFaceLeavesItsCellOpen) {
  const double h = 0.02;
  const CelGrid g = make_plane_strain_grid(32, 4, h);
  RigidWall gate;  // the seed chute's gate plate, 0.57 to 0.61 m, on 20 mm cells
  gate.points = {{0.61, 1.0}, {0.61, 0.0}, {0.57, 0.0}, {0.57, 1.0}};
  const std::vector<PlacedWall> walls = {PlacedWall(gate, 0.0)};
  CellFields cells;
  cells.resize(g.cell_count());
  mark_wall_cells(g, walls, cells);
  for (int j = 0; j < 4; ++j) {
    for (int i : {28, 30}) {  // centres on the faces, to round-off
      EXPECT_NEAR(distance_to_walls(walls, g.cell_centre(g.cell(i, j))), 0.0, 1e-15);
      EXPECT_EQ(cells.solid[g.cell(i, j)], 0) << "cell " << i << ", " << j;
    }
    EXPECT_EQ(cells.solid[g.cell(27, j)], 0);
    EXPECT_EQ(cells.solid[g.cell(29, j)], kSolidInsideWall);
    EXPECT_EQ(cells.solid[g.cell(31, j)], 0);
  }
}

// No node moves into the staircase: a corner of a wall cell farther from the wall than the
// contact distance (node (10, 20) mm, 5.4 mm from the line, a corner of the solid cell (1, 1))
// loses its velocity into the wall like a node in contact, and reacts on the wall; a node as far
// or farther that is no wall cell's corner keeps its velocity.
TEST(CelRigidWall, CornersOfWallCellsAreHeldByTheirNearestWall) {
  const CelGrid g = make_plane_strain_grid(4, 4, kCell);
  const NodeVector n = NodeVector(-0.5, 1.0).normalized();
  const RigidWall wall = make_half_plane_wall({0.0, 0.009}, n);  // frictionless
  const std::vector<PlacedWall> walls = {PlacedWall(wall, 0.0)};
  CellFields cells;
  cells.resize(g.cell_count());
  mark_wall_cells(g, walls, cells);
  NodeFields nodes;
  nodes.resize(g.node_count());
  const NodeVector falling(0.3, -1.0);  // into the wall: v . n < 0
  for (std::size_t a = 0; a < g.node_count(); ++a) {
    nodes.mass[a] = 1.0;
    nodes.velocity[a] = falling;
  }
  const WallContactOptions options;  // d_c = h / 2
  const auto reaction = apply_wall_contact(g, walls, options, 1e-3, 0.0, cells, nodes);
  const std::size_t held = g.node(1, 2), free = g.node(2, 4);
  ASSERT_GT(distance_to_walls(walls, g.node_position(held)), options.contact_distance * kCell);
  ASSERT_EQ(cells.solid[g.cell(1, 1)], kSolidInsideWall);
  EXPECT_NEAR(nodes.velocity[held].dot(n), 0.0, 1e-15);
  EXPECT_NEAR((nodes.velocity[held] - falling).norm(), -falling.dot(n), 1e-15);  // only v_n removed
  // Node (20, 40): 21 mm from the line, no solid cell around it.
  EXPECT_GT(distance_to_walls(walls, g.node_position(free)), distance_to_walls(walls, g.node_position(held)));
  EXPECT_EQ(nodes.velocity[free], falling);
  EXPECT_GT(reaction.at(0).dot(n), 0.0);  // the wall pushes the material out
}

// The velocity a node takes against the given walls (in this order), with the walls' reactions.
struct Contacted {
  NodeVector velocity;
  std::vector<NodeVector> reaction;
};
Contacted contact_of(const std::vector<RigidWall>& rigid, const NodeVector& position,
                     const NodeVector& v) {
  const CelGrid g = make_plane_strain_grid(4, 4, kCell);
  std::vector<PlacedWall> walls;
  for (const auto& w : rigid) walls.emplace_back(w, 0.0);
  CellFields cells;
  cells.resize(g.cell_count());
  NodeFields nodes;
  nodes.resize(g.node_count());
  const std::size_t a = g.node(static_cast<int>(std::lround(position.x() / kCell)),
                               static_cast<int>(std::lround(position.y() / kCell)));
  nodes.mass[a] = 1.0;
  nodes.velocity[a] = v;
  const auto reaction = apply_wall_contact(g, walls, WallContactOptions{}, 1.0, 0.0, cells, nodes);
  return {nodes.velocity[a], reaction};
}

// A node pressed into a corner takes the nearest velocity that moves into neither wall, whichever
// wall comes first. A wedge's outlet lip (a 30 deg wall meeting the closed gate) falling down and
// outward stops, both walls pushing; projected on the sloped wall and then the gate it slid toward
// the axis at a third of its speed (the low-friction step collapse). At an obtuse junction (a
// bin's vertical wall meeting the 30 deg wall) a node moving down and out slides along the
// sloped wall at exactly its frictionless projection, (-0.183, -0.317) m/s for (1, -1) m/s.
TEST(CelRigidWall, NodeInACornerTakesTheNearestVelocityMovingIntoNeitherWall) {
  const double mu = std::tan(2.5 * std::numbers::pi / 180.0);
  const NodeVector sloped_normal(-std::cos(std::numbers::pi / 6), std::sin(std::numbers::pi / 6));
  const RigidWall sloped = make_half_plane_wall({0.02, 0.0}, sloped_normal, mu);
  const RigidWall gate = make_half_plane_wall({0.0, 0.0}, {0.0, 1.0}, mu);
  const NodeVector falling(0.3, -1.0), lip(0.02, 0.0);  // down and out, into both
  for (const bool gate_first : {false, true}) {
    const Contacted c = contact_of(
        gate_first ? std::vector{gate, sloped} : std::vector{sloped, gate}, lip, falling);
    EXPECT_NEAR(c.velocity.norm(), 0.0, 1e-15);
    EXPECT_NEAR((c.reaction[0] + c.reaction[1] + falling).norm(), 0.0, 1e-15);  // m (v* - v) / dt
    EXPECT_GT(c.reaction[gate_first ? 0 : 1].y(), 0.0);                         // both walls push
    EXPECT_GT(c.reaction[gate_first ? 1 : 0].dot(sloped_normal), 0.0);
  }

  const RigidWall bin = make_half_plane_wall({0.02, 0.0}, {-1.0, 0.0});
  const RigidWall smooth = make_half_plane_wall({0.02, 0.0}, sloped_normal);
  for (const bool bin_first : {false, true}) {
    const Contacted c = contact_of(bin_first ? std::vector{bin, smooth} : std::vector{smooth, bin},
                                   lip, {1.0, -1.0});
    EXPECT_NEAR(c.velocity.x(), -0.25 * (std::sqrt(3.0) - 1.0), 1e-12);
    EXPECT_NEAR(c.velocity.y(), -0.25 * (3.0 - std::sqrt(3.0)), 1e-12);
  }
}

}  // namespace
}  // namespace feedflow::cel
