// The pair loop's vectorised batches (fullsim/dem/contact_batch.hpp) against the composed law
// evaluated one contact at a time, and the AVX2 lanes against the generic ones.
#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <vector>

#include "fullsim/dem/force_kernel.hpp"
#include "models/contact/contact_law.hpp"
#include "tests/support/pine_table2.hpp"

namespace feedflow {
namespace {

constexpr double kPairRadius = 1.5e-3;

// Isolated pairs of pine spheres on a grid of 10 R spacing, each touching with a random
// overlap up to 0.15 R, random direction, velocities and spins (some spins zero). Between
// `steps` calls of the kernel the positions stay put, so the history of each contact builds
// up (sticking first, sliding later: the tangential spring grows by v_t dt per call).
struct PairField {
  ParticleStore particles;
  SimulationBox box{Vec3::Constant(-0.01), Vec3::Constant(0.1), {false, false, false}};
  NeighbourList list;
  std::vector<Wall> walls;
  std::vector<MeshWall> meshes;
  std::vector<Vec3> start;              // positions as built
  std::vector<Vec3> velocity_at_start;  // velocities as built

  PairField(std::size_t pairs, std::size_t history) : list(0.3 * kPairRadius, history) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t k = 0; k < pairs; ++k) {
      const Vec3 a = 10.0 * kPairRadius *
                     Vec3(static_cast<double>(k % 5), static_cast<double>(k / 5 % 5),
                          static_cast<double>(k / 25));
      const Vec3 dir = Vec3(u(rng), u(rng), u(rng)).normalized();
      const double overlap = 0.075 * kPairRadius * (1.0 + u(rng));
      const Vec3 spin_i = k % 5 == 0 ? Vec3(Vec3::Zero()) : Vec3(Vec3(u(rng), u(rng), u(rng)) * 30.0);
      const Vec3 spin_j = k % 5 == 0 ? Vec3(Vec3::Zero()) : Vec3(Vec3(u(rng), u(rng), u(rng)) * 30.0);
      particles.add(a, kPairRadius, 390.0, 0.0, Vec3(u(rng), u(rng), u(rng)) * 0.5);
      particles.add(a + (2.0 * kPairRadius - overlap) * dir, kPairRadius, 390.0, 0.0,
                    Vec3(u(rng), u(rng), u(rng)) * 0.5);
      particles.angular_velocity[2 * k] = spin_i;
      particles.angular_velocity[2 * k + 1] = spin_j;
    }
    list.rebuild(particles, box);
    start = particles.position;
    velocity_at_start = particles.velocity;
  }

  // Call s of a breathing run: the second sphere of each pair moved along the pair's axis, the
  // overlap from 1.3 times its start down to 0.05 times and back every 12 calls, with the
  // matching velocity.
  void breathe(int s) {
    constexpr double kPeriod = 12.0;
    const double phase = 2.0 * std::numbers::pi * s / kPeriod;
    for (std::size_t k = 0; k < particles.size() / 2; ++k) {
      const Vec3 axis = (start[2 * k + 1] - start[2 * k]).normalized();
      const double overlap = 2.0 * kPairRadius - (start[2 * k + 1] - start[2 * k]).norm();
      const double shift = overlap * (0.625 * (1.0 - std::cos(phase)) - 0.3);  // -0.3 .. 0.95
      const double speed =
          overlap * 0.625 * std::sin(phase) * (2.0 * std::numbers::pi / kPeriod) / 1e-5;
      particles.position[2 * k + 1] = start[2 * k + 1] + shift * axis;
      particles.velocity[2 * k + 1] = velocity_at_start[2 * k + 1] + speed * axis;
    }
  }

  // Forces and torques of `steps` kernel calls (the last one), in slot order. With `breathing`,
  // the second sphere of each pair moves along the pair's axis between calls (overlap 1.3 down to
  // 0.05 of its start and back, with the matching velocity), so the contacts load, unload below
  // their plastic overlap and reload: every branch of the hysteretic laws.
  std::vector<Vec3> run(ForceKernel& kernel, int lane_bits, int steps, bool breathing = false) {
    DeepestOverlap pairs, at_walls;
    double wall_seconds = 0.0;
    for (int s = 0; s < steps; ++s) {
      if (breathing) breathe(s);
      for (std::size_t i = 0; i < particles.size(); ++i) {
        particles.force[i].setZero();
        particles.torque[i].setZero();
      }
      ForceContext c{particles, list, box, walls, meshes, 0.0, 1e-5, false};
      c.max_lane_bits = lane_bits;
      kernel.add_contact_forces(c, pairs, at_walls, wall_seconds);
    }
    std::vector<Vec3> out = particles.force;
    out.insert(out.end(), particles.torque.begin(), particles.torque.end());
    return out;
  }
};

std::vector<ContactLawChoice> compositions() {
  return {choose_contact_law("hertz", "mindlin", "cdt", "none"),
          choose_contact_law("hertz", "history", "cdt_clamped", "none"),
          choose_contact_law("hooke", "history", "epsd2", "none"),
          choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "none"),
          choose_contact_law("hysteretic_nonlinear1", "mindlin", "none", "k_nc")};
}

// The contact of pair k (spheres 2k + 1 and 2k, one row of the list) as the law sees it.
ContactInput pair_input(const ParticleStore& p, std::size_t k) {
  const std::size_t i = 2 * k + 1, j = 2 * k;
  const Vec3 d = p.position[i] - p.position[j];
  ContactInput in;
  in.overlap = 2.0 * kPairRadius - d.norm();
  in.normal = d.normalized();
  const double ci = kPairRadius - 0.5 * in.overlap;
  const Vec3 vr = p.velocity[i] - p.velocity[j];
  in.normal_velocity = vr.dot(in.normal);
  in.tangential_velocity = vr - in.normal_velocity * in.normal +
                           in.normal.cross(ci * (p.angular_velocity[i] + p.angular_velocity[j]));
  in.relative_angular_velocity = p.angular_velocity[i] - p.angular_velocity[j];
  in.effective_radius = 0.5 * kPairRadius;
  in.effective_mass = 0.5 * p.mass[i];
  in.effective_inertia = 0.5 * p.inertia[i];
  in.dt = 1e-5;
  return in;
}

// Each composition's batch gives every pair the force and torques of ContactLaw::evaluate
// applied to that contact alone, over 40 calls (history growing from sticking into sliding).
TEST(ContactBatch, GivesEachPairTheForceOfTheComposedLaw) {
  for (const ContactLawChoice& choice : compositions()) {
    const DemParameters dem = testing::pine_table2(kPairRadius);
    auto kernel = make_force_kernel(choice, dem);
    PairField field(37, kernel->history_size());  // 37: one full batch of 32 and a part
    const std::vector<Vec3> batched = field.run(*kernel, 512, 40);
    with_contact_law(choice, [&](auto tag) {
      using Law = typename decltype(tag)::type;
      const Law law(dem.particle_particle);
      const ParticleStore& p = field.particles;
      std::size_t sliding = 0;
      for (std::size_t k = 0; k < p.size() / 2; ++k) {
        const std::size_t i = 2 * k + 1, j = 2 * k;  // the list keeps a pair under one row
        const ContactInput in = pair_input(p, k);
        const double ci = kPairRadius - 0.5 * in.overlap;
        typename Law::History h{};
        ContactOutput out;
        for (int s = 0; s < 40; ++s) out = law.evaluate(in, h);
        const Vec3 f = out.normal_force * in.normal + out.tangential_force;
        const Vec3 ti = out.rolling_torque - ci * in.normal.cross(out.tangential_force);
        const double scale = f.norm() + 1e-30;
        const std::size_t n = p.size();
        EXPECT_LT((batched[i] - f).norm(), 1e-12 * scale) << Law::name() << " pair " << k;
        EXPECT_LT((batched[j] + f).norm(), 1e-12 * scale) << Law::name() << " pair " << k;
        EXPECT_LT((batched[n + i] - ti).norm(), 1e-12 * (ti.norm() + scale * kPairRadius))
            << Law::name() << " pair " << k;
        if constexpr (requires { law.tangential().friction(); }) {
          const double cap = law.tangential().friction() * std::abs(out.normal_force);
          if (cap > 0.0 && out.tangential_force.norm() > 0.999 * cap) ++sliding;
        }
      }
      if (!choice.tangential.is<NoTangential>()) {
        EXPECT_GT(sliding, 0u) << Law::name() << ": some contacts must have reached the cap";
      }
    });
  }
}

// The AVX-512 and AVX2 lanes (where the processor has them) and the generic lanes give the same
// forces and torques bit for bit, for every composition.
TEST(ContactBatch, WideLanesGiveTheSameBitsAsTheGenericLanes) {
  if (lane_bits_available() < 256) GTEST_SKIP() << "no AVX2 on this processor";
  for (const ContactLawChoice& choice : compositions()) {
    const DemParameters dem = testing::pine_table2(kPairRadius);
    std::vector<std::vector<Vec3>> runs;
    std::string name;
    for (int bits = 128; bits <= lane_bits_available(); bits *= 2) {
      auto kernel = make_force_kernel(choice, dem);
      name = kernel->name();
      PairField field(70, kernel->history_size());
      runs.push_back(field.run(*kernel, bits, 25));
    }
    for (std::size_t r = 1; r < runs.size(); ++r) {
      ASSERT_EQ(runs[r].size(), runs[0].size());
      for (std::size_t k = 0; k < runs[0].size(); ++k) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(runs[r][k][c], runs[0][k][c]) << name << " lanes " << r;
      }
    }
  }
}

// The hysteretic laws through every branch (loading, unloading on the ramp and below the
// plastic overlap, reloading from there; with k_nc also the -k_c delta floor): each pair's force
// from the batch is that of the composed law evaluated alone on the same motion, and the AVX2
// and AVX-512 lanes give the generic lanes' bits, over 60 breathing calls.
TEST(ContactBatch, HystereticBranchesGiveTheSameBitsInEveryLaneWidth) {
  for (const ContactLawChoice& choice :
       {choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "none"),
        choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "k_nc")}) {
    const DemParameters dem = testing::pine_table2(kPairRadius);
    std::vector<std::vector<Vec3>> runs;
    for (int bits = 128; bits <= std::max(128, lane_bits_available()); bits *= 2) {
      auto kernel = make_force_kernel(choice, dem);
      PairField field(70, kernel->history_size());
      runs.push_back(field.run(*kernel, bits, 60, true));
    }
    with_contact_law(choice, [&](auto tag) {
      using Law = typename decltype(tag)::type;
      const Law law(dem.particle_particle);
      PairField alone(70, 0);
      std::size_t below_plastic = 0;
      for (std::size_t k = 0; k < 70; ++k) {
        typename Law::History h{};
        ContactOutput out;
        for (int s = 0; s < 60; ++s) {
          alone.breathe(s);
          const ContactInput in = pair_input(alone.particles, k);
          out = law.evaluate(in, h);
          if (in.overlap < h[hysteretic_slot::plastic_overlap]) ++below_plastic;
        }
        const ContactInput in = pair_input(alone.particles, k);
        const Vec3 f = out.normal_force * in.normal + out.tangential_force;
        EXPECT_LT((runs[0][2 * k + 1] - f).norm(), 1e-12 * (f.norm() + 1e-30))
            << Law::name() << " pair " << k;
      }
      EXPECT_GT(below_plastic, 70u * 5) << Law::name() << ": the branch below delta0 must be taken";
    });
    for (std::size_t r = 1; r < runs.size(); ++r)
      for (std::size_t k = 0; k < runs[0].size(); ++k)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(runs[r][k][c], runs[0][k][c]) << "lanes " << r;
  }
}

}  // namespace
}  // namespace feedflow
