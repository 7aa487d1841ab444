#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "models/core/errors.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

// An oblique, frictional collision of two spheres across a periodic boundary: the moving
// sphere wraps (its position is brought back into the box at a rebuild during the contact),
// the contact keeps its tangential history, and the outcome equals the same collision in an
// open box to round-off.
TEST(DemBoundaries, PeriodicCrossingKeepsTheContactAndItsHistory) {
  DemSettings s = hertz_settings(0.5, 0.5, 0.0);
  s.gravity = Vec3::Zero();
  s.skin_fraction = 0.05;
  const double L = 0.02;
  // Two spheres drifting together at 1 m/s across x = L while they collide obliquely (normal
  // mostly along y, relative slip along x).
  auto collide = [&](bool periodic) {
    ParticleStore p;
    p.add(Vec3(L - 0.5e-3, 0.01, 0.01), kRadius, kDensity, 0, Vec3(1.05, 0.05, 0));
    p.add(Vec3(L - 0.5e-3, 0.01 + 3.01e-3, 0.01), kRadius, kDensity, 0, Vec3(0.95, -0.05, 0));
    SimulationBox box{Vec3::Zero(), Vec3(periodic ? L : 1.0, 0.02, 0.02), {periodic, false, false}};
    DemEngine e(s, box, p);
    std::ostringstream plan;
    e.prepare(plan);
    bool wrapped_in_contact = false;
    double max_history = 0.0;
    for (int k = 0; k < 150; ++k) {
      e.run_steps(1);
      const double* h = e.neighbours().find_history(0, 1);
      const double hn = h ? Vec3(h[0], h[1], h[2]).norm() : 0.0;
      max_history = std::max(max_history, hn);
      const ParticleStore& q = e.particles();
      for (std::size_t i = 0; i < q.size(); ++i)
        if (q.id[i] == 0 && q.position[i].x() < L / 2 && hn > 0.0) wrapped_in_contact = true;
    }
    const ParticleStore& q = e.particles();
    std::array<Vec3, 4> out;
    for (std::size_t i = 0; i < 2; ++i) {
      out[q.id[i]] = q.velocity[i];
      out[2 + q.id[i]] = q.angular_velocity[i];
    }
    return std::make_tuple(out, wrapped_in_contact, max_history);
  };
  const auto [periodic, wrapped, history] = collide(true);
  const auto [open, open_wrapped, open_history] = collide(false);
  EXPECT_TRUE(wrapped) << "the moving sphere did not wrap while in contact";
  EXPECT_FALSE(open_wrapped);
  EXPECT_GT(history, 1e-6);
  std::printf("periodic collision: spin after %.6g rad/s (open box %.6g), max |xi| %.3g m\n",
              periodic[2].z(), open[2].z(), history);
  EXPECT_GT(std::abs(open[2].z()), 1.0);  // friction spun the spheres
  for (int k = 0; k < 4; ++k) EXPECT_LT((periodic[k] - open[k]).norm(), 1e-9) << k;
}

// Spheres falling through an outlet sink are removed and their mass booked exactly, with the
// time of each removal.
TEST(DemBoundaries, OutletSinkRemovesAndBooksTheMass) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  ParticleStore p;
  add_lattice(p, Vec3(0.003, 0.003, 0.02), 4, 4, 3, 0.0036, 0.0);
  const double mass = p.total_mass();
  SimulationBox box{Vec3(0, 0, -0.01), Vec3(0.02, 0.02, 0.04), {false, false, false}};
  DemEngine e(s, box, p);
  e.set_outlet_sink(OutletSink::plane(Vec3::Zero(), -Vec3::UnitZ()));
  std::ostringstream plan;
  e.prepare(plan);
  e.advance_to(0.1);
  const auto& sink = *e.outlet_sink();
  EXPECT_EQ(e.particles().size(), 48u - sink.removed_count());
  e.advance_to(0.2);
  EXPECT_EQ(e.particles().size(), 0u);
  EXPECT_EQ(sink.removed_count(), 48u);
  EXPECT_EQ(sink.removed_mass(), mass);  // the same masses summed in the same order
  for (const auto& ev : sink.events()) {
    EXPECT_GT(ev.time, 0.06);  // free fall of 2 cm takes 0.064 s
    EXPECT_LT(ev.time, 0.2);
  }
}

// A gate removed at a given time: a sphere resting on it stays put before t = 0.05 s and falls
// freely after (z drops by g t^2 / 2 within 1 %), its wall history cleared.
TEST(DemBoundaries, WallRemovedAtItsTimeLetsTheSphereFall) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  ParticleStore p;
  p.add(Vec3(0.01, 0.01, 0.0115), kRadius, kDensity);
  SimulationBox box{Vec3::Zero(), Vec3(0.02, 0.02, 0.02), {false, false, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("gate", Vec3(0, 0, 0.01), Vec3::UnitZ()).removed_at(0.05));
  std::ostringstream plan;
  e.prepare(plan);
  EXPECT_NE(plan.str().find("removed at t = 0.05 s"), std::string::npos) << plan.str();
  e.advance_to(0.0499);
  const double resting = e.particles().position[0].z();
  EXPECT_NEAR(resting, 0.0115, 1e-5);
  e.advance_to(0.05);
  const double t0 = e.time();
  e.advance_to(0.07);
  const double fall = e.particles().position[0].z() - resting;
  const double t = e.time() - t0;
  EXPECT_NEAR(fall, -0.5 * 9.81 * t * t, 0.01 * 0.5 * 9.81 * t * t);
}

// A translating wall: a floor rising at 0.1 m/s carries a resting sphere with it (its centre
// follows the floor to within the Hertz overlap of its weight).
TEST(DemBoundaries, TranslatingFloorCarriesTheSphere) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  ParticleStore p;
  p.add(Vec3(0.01, 0.01, kRadius), kRadius, kDensity);
  SimulationBox box{Vec3::Zero(), Vec3(0.02, 0.02, 0.04), {false, false, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("piston", Vec3::Zero(), Vec3::UnitZ()).moving(0.1 * Vec3::UnitZ(),
                                                                        Vec3::Zero()));
  std::ostringstream plan;
  e.prepare(plan);
  e.advance_to(0.1);
  const double floor = e.walls()[0].point().z();
  EXPECT_NEAR(floor, 0.01, 1e-4);
  EXPECT_NEAR(e.particles().position[0].z(), floor + kRadius, 1e-5);
  EXPECT_NEAR(e.particles().velocity[0].z(), 0.1, 1e-2);
}

// The force and torque a face puts on a sphere pressed against it by its weight (gravity along
// -y onto the plane y = 0) while sliding along x and spinning about z: after 0.02 s of sliding,
// the contact's share of the particle's force and its torque.
struct FaceContact {
  Vec3 force;   // contact force on the sphere [N]
  Vec3 torque;  // [N m]
  Vec3 velocity, angular_velocity;
  std::string plan;
};
FaceContact slide_on_face(WallContactSet set) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.8);
  s.material.particle_wall = soft_contact(0.3, 0.2, 0.6);
  s.gravity = Vec3(0.0, -9.81, 0.0);
  ParticleStore p;
  p.add(Vec3(0.01, kRadius, 0.01), kRadius, kDensity, 0, Vec3(0.5, 0.0, 0.0));
  p.angular_velocity[0] = Vec3(0.0, 0.0, 50.0);
  SimulationBox box{Vec3::Zero(), Vec3(0.2, 0.02, 0.02), {false, false, false}};
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("face", Vec3::Zero(), Vec3::UnitY()).with_contact_set(set));
  std::ostringstream plan;
  e.prepare(plan);
  e.advance_to(0.02);
  const ParticleStore& q = e.particles();
  return {q.force[0] - q.mass[0] * s.gravity, q.torque[0], q.velocity[0], q.angular_velocity[0],
          plan.str()};
}

// A frictionless face carries the normal load only: a sphere sliding and spinning on it feels
// no tangential force and no rolling torque (its slip speed and spin stay exactly as launched),
// while on the frictional P-W face it slides on its Coulomb limit |F_t| = mu F_n (mu = 0.2)
// and is spun down.
TEST(DemBoundaries, FrictionlessFaceCarriesNoTangentialForceOrTorque) {
  const FaceContact smooth = slide_on_face(WallContactSet::frictionless);
  EXPECT_NE(smooth.plan.find("frictionless"), std::string::npos) << smooth.plan;
  EXPECT_NEAR(smooth.force.y(),
              kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3) * 9.81,
              0.05 * smooth.force.y());  // resting on the face under its weight
  EXPECT_EQ(smooth.force.x(), 0.0);
  EXPECT_EQ(smooth.force.z(), 0.0);
  EXPECT_EQ(smooth.torque.norm(), 0.0);
  EXPECT_EQ(smooth.velocity.x(), 0.5);
  EXPECT_EQ(smooth.angular_velocity.z(), 50.0);

  const FaceContact rough = slide_on_face(WallContactSet::particle_wall);
  EXPECT_EQ(rough.plan.find("frictionless"), std::string::npos);
  const double fn = rough.force.y();
  EXPECT_GT(fn, 0.0);
  EXPECT_NEAR(std::hypot(rough.force.x(), rough.force.z()), 0.2 * fn, 1e-9 * fn);
  EXPECT_LT(rough.force.x(), 0.0);  // against the slip
  EXPECT_GT(rough.torque.norm(), 0.0);
  EXPECT_LT(rough.velocity.x(), 0.5);
}

// A step far above the stable one is refused; forced, the blow-up guard stops the run with
// the step, the particle id, its position and a safe time step.
TEST(DemBoundaries, BlowUpGuardFiresWithItsMessage) {
  DemSettings s = hertz_settings(0.3, 0.5, 0.0);
  ParticleStore p;
  p.add(Vec3(0.01, 0.01, 0.002), kRadius, kDensity, 0, Vec3(0, 0, -1.0));
  SimulationBox box{Vec3::Zero(), Vec3(0.02, 0.02, 0.02), {false, false, false}};
  DemEngine probe(s, box, p);
  std::ostringstream plan;
  probe.prepare(plan);
  s.requested_time_step = 100 * probe.time_step();
  {
    DemEngine e(s, box, p);
    e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
    EXPECT_THROW(e.prepare(plan), InputError);
  }
  s.force_time_step = true;
  DemEngine e(s, box, p);
  e.add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  e.prepare(plan);
  try {
    e.run_steps(50);
    FAIL() << "no blow-up detected";
  } catch (const NumericalFailure& f) {
    const std::string m = f.what();
    std::printf("guard: %s\n", m.c_str());
    EXPECT_NE(m.find("at step"), std::string::npos);
    EXPECT_NE(m.find("particle id 0"), std::string::npos);
    EXPECT_NE(m.find("safe time step"), std::string::npos);
    EXPECT_NE(m.find("exceeds 0.3 R"), std::string::npos);
  }
}

// A row of three frictionless spheres squeezed between two walls, the middle one 1e-6 R off
// the row's line: free, the contact forces push it out of the line (the buckling that lifts a
// one-layer slab onto its faces once its contacts slide); held in the plane normal to y, it
// stays exactly where it was, and so do the others (no velocity along y, no spin about x or z).
TEST(DemBoundaries, PlaneHoldKeepsACompressedRowInItsPlane) {
  DemSettings s = hertz_settings(0.5, 0.0, 0.0);
  s.gravity = Vec3::Zero();
  const double r = kRadius, squeeze = 0.02 * r, offset = 1e-6 * r;
  auto run = [&](bool hold) {
    ParticleStore p;
    p.add(Vec3(0.01 - 2 * r + squeeze, 0.01, 0.01), r, kDensity);
    p.add(Vec3(0.01, 0.01 + offset, 0.01), r, kDensity);
    p.add(Vec3(0.01 + 2 * r - squeeze, 0.01, 0.01), r, kDensity);
    DemEngine e(s, SimulationBox{Vec3::Zero(), Vec3(0.02, 0.02, 0.02), {false, false, false}}, p);
    e.add_wall(Wall::plane("left", Vec3(0.01 - 3 * r + squeeze, 0, 0), Vec3::UnitX()));
    e.add_wall(Wall::plane("right", Vec3(0.01 + 3 * r - squeeze, 0, 0), -Vec3::UnitX()));
    if (hold) e.hold_in_plane(1);
    std::ostringstream plan;
    e.prepare(plan);
    if (hold) {
      EXPECT_NE(plan.str().find("plane hold"), std::string::npos) << plan.str();
    }
    e.advance_to(0.02);
    return e;
  };
  const DemEngine free = run(false), held = run(true);
  const auto middle = [](const DemEngine& e) {
    const ParticleStore& q = e.particles();
    for (std::size_t i = 0; i < q.size(); ++i)
      if (q.id[i] == 1) return q.position[i].y();
    return 0.0;
  };
  std::printf("squeezed row after 0.02 s: middle sphere %.3g m off the line free, %.3g m held\n",
              middle(free) - 0.01, middle(held) - 0.01);
  EXPECT_GT(std::abs(middle(free) - 0.01), 1e3 * offset);  // pushed out of the line
  EXPECT_EQ(middle(held), 0.01 + offset);                   // held in its own plane, to the bit
  const ParticleStore& q = held.particles();
  for (std::size_t i = 0; i < q.size(); ++i) {
    EXPECT_EQ(q.velocity[i].y(), 0.0);
    EXPECT_EQ(q.angular_velocity[i].x(), 0.0);
    EXPECT_EQ(q.angular_velocity[i].z(), 0.0);
  }
}

}  // namespace
}  // namespace feedflow
