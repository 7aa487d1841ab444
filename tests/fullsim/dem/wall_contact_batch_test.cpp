// The wall loop's vectorised batches (fullsim/dem/wall_contact_batch.hpp) against the composed
// law evaluated one contact at a time, and the AVX2 and AVX-512 lanes against the generic ones.
#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <vector>

#include "fullsim/dem/force_kernel.hpp"
#include "models/contact/contact_law.hpp"
#include "tests/support/pine_table2.hpp"

namespace feedflow {
namespace {

constexpr double kRadius = 1.5e-3;
constexpr double kDt = 1e-5;

// Pine spheres on a floor (z = 0, the P-W set, sliding at 2 m/s along x) in a row along x,
// 10 R apart, each pressed into it by a random overlap up to 0.15 R, with random velocities and
// spins (every fifth spin zero). The first few also rest on a frictionless side face (x = 0,
// the P-W set without friction), so one particle takes contacts of both sets. Between calls the
// particles are moved along z, so the floor contacts load, unload and reload.
struct WallField {
  ParticleStore particles;
  SimulationBox box{Vec3::Constant(-0.01), Vec3(1.0, 0.1, 0.1), {false, false, false}};
  NeighbourList list;
  std::vector<Wall> walls;
  std::vector<MeshWall> meshes;
  std::vector<Vec3> start;
  static constexpr std::size_t kAtTheFace = 6;  // particles touching the side face too

  WallField(std::size_t count, std::size_t history) : list(0.3 * kRadius, history) {
    walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ())
                        .moving(Vec3(2.0, 0.0, 0.0), Vec3::Zero()));
    walls.push_back(Wall::plane("face", Vec3::Zero(), Vec3::UnitX())
                        .with_contact_set(WallContactSet::frictionless));
    particles.set_wall_history_stride(walls.size() * history);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t k = 0; k < count; ++k) {
      const double floor_overlap = 0.075 * kRadius * (1.0 + u(rng));
      const double x = k < kAtTheFace ? kRadius - 0.05 * kRadius * (1.0 + u(rng))
                                      : 10.0 * kRadius * static_cast<double>(k + 1);
      const double y = k < kAtTheFace ? 10.0 * kRadius * static_cast<double>(k) : 0.0;
      particles.add(Vec3(x, y, kRadius - floor_overlap), kRadius, 390.0, 0.0,
                    Vec3(u(rng), u(rng), u(rng)) * 0.5);
      particles.angular_velocity[k] =
          k % 5 == 0 ? Vec3(Vec3::Zero()) : Vec3(Vec3(u(rng), u(rng), u(rng)) * 30.0);
      if (k < kAtTheFace) particles.velocity[k].x() = 0.0;  // resting on the face
    }
    list.rebuild(particles, box);
    start = particles.position;
  }

  // Call s: each particle's height breathes about its start (down 0.3 and up 0.9 of its floor
  // overlap, period 12 calls), with the matching vertical velocity.
  void breathe(int s) {
    constexpr double kPeriod = 12.0;
    const double phase = 2.0 * std::numbers::pi * s / kPeriod;
    for (std::size_t k = 0; k < particles.size(); ++k) {
      const double overlap = kRadius - start[k].z();
      particles.position[k].z() = start[k].z() + overlap * (0.6 * (1.0 - std::cos(phase)) - 0.3);
      particles.velocity[k].z() =
          overlap * 0.6 * std::sin(phase) * (2.0 * std::numbers::pi / kPeriod) / kDt;
    }
  }

  // Forces and torques after `steps` calls of the kernel (those of the last call, at call
  // steps - 1 of the breathing).
  std::vector<Vec3> run(ForceKernel& kernel, int lane_bits, int steps) {
    DeepestOverlap pairs, at_walls;
    double wall_seconds = 0.0;
    for (int s = 0; s < steps; ++s) {
      breathe(s);
      for (std::size_t i = 0; i < particles.size(); ++i) {
        particles.force[i].setZero();
        particles.torque[i].setZero();
      }
      ForceContext c{particles, list, box, walls, meshes, 0.0, kDt, false};
      c.max_lane_bits = lane_bits;
      kernel.add_contact_forces(c, pairs, at_walls, wall_seconds);
    }
    std::vector<Vec3> out = particles.force;
    out.insert(out.end(), particles.torque.begin(), particles.torque.end());
    return out;
  }
};

// The floor contact of particle k as the law sees it (the wall is the second body).
ContactInput floor_input(const WallField& f, std::size_t k) {
  const ParticleStore& p = f.particles;
  ContactInput in;
  in.overlap = kRadius - p.position[k].z();
  in.normal = Vec3::UnitZ();
  const double ci = kRadius - in.overlap;
  const Vec3 vr = p.velocity[k] - Vec3(2.0, 0.0, 0.0);
  in.normal_velocity = vr.z();
  in.tangential_velocity = vr - in.normal_velocity * in.normal +
                           in.normal.cross(ci * p.angular_velocity[k]);
  in.relative_angular_velocity = p.angular_velocity[k];
  in.effective_radius = kRadius;
  in.effective_mass = p.mass[k];
  in.effective_inertia = p.inertia[k];
  in.dt = kDt;
  return in;
}

// Each particle (70: two full batches and a part) takes the force and torque of
// ContactLaw::evaluate applied to its floor contact alone on the same motion, plus for those on
// the face a push along +x and no torque (the frictionless set), through every branch
// of the hysteretic laws (37 calls: three periods of breathing, ending at the deepest point); and the AVX2 and AVX-512 lanes give the generic lanes' bits for every
// particle, those on both walls (two parameter sets in one particle's sum) included.
TEST(WallContactBatch, GivesEachContactTheComposedLawInEveryLaneWidth) {
  for (const ContactLawChoice& choice :
       {choose_contact_law("hertz", "mindlin", "cdt", "none"),
        choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "none"),
        choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "k_nc")}) {
    const DemParameters dem = testing::pine_table2(kRadius);
    std::vector<std::vector<Vec3>> runs;
    std::string name;
    for (int bits = 128; bits <= std::max(128, lane_bits_available()); bits *= 2) {
      auto kernel = make_force_kernel(choice, dem);
      name = kernel->name();
      WallField field(70, kernel->history_size());
      runs.push_back(field.run(*kernel, bits, 37));
    }
    with_contact_law(choice, [&](auto tag) {
      using Law = typename decltype(tag)::type;
      const Law law(dem.particle_wall);
      WallField alone(70, 0);
      std::size_t sliding = 0;
      for (std::size_t k = 0; k < 70; ++k) {
        typename Law::History h{};
        ContactOutput out;
        for (int s = 0; s < 37; ++s) {
          alone.breathe(s);
          out = law.evaluate(floor_input(alone, k), h);
        }
        EXPECT_GT(out.normal_force, 0.0) << name << " particle " << k;  // the last call presses
        const ContactInput in = floor_input(alone, k);
        const Vec3 f = out.normal_force * in.normal + out.tangential_force;
        const Vec3 t = out.rolling_torque - (kRadius - in.overlap) * in.normal.cross(out.tangential_force);
        const double scale = f.norm() + 1e-30;
        // On the face too: the rest is the face's push along +x, without friction (no torque).
        const Vec3 rest = runs[0][k] - f;
        if (k < WallField::kAtTheFace) {
          EXPECT_GT(rest.x(), 1e-3 * scale) << name << " particle " << k;
          EXPECT_LT(Vec3(0.0, rest.y(), rest.z()).norm(), 1e-12 * scale) << name << " particle " << k;
        } else {
          EXPECT_LT(rest.norm(), 1e-12 * scale) << name << " particle " << k;
        }
        EXPECT_LT((runs[0][70 + k] - t).norm(), 1e-12 * (t.norm() + scale * kRadius))
            << name << " particle " << k;
        const double cap = dem.particle_wall.friction * std::abs(out.normal_force);
        if (cap > 0.0 && out.tangential_force.norm() > 0.999 * cap) ++sliding;
      }
      EXPECT_GT(sliding, 0u) << name << ": some floor contacts must slide";
    });
    for (std::size_t r = 1; r < runs.size(); ++r)
      for (std::size_t k = 0; k < runs[0].size(); ++k)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(runs[r][k][c], runs[0][k][c]) << name << " lanes " << r;
  }
}

}  // namespace
}  // namespace feedflow
