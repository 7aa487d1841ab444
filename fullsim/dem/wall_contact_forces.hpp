#pragma once
// The particle-wall contacts of one composed contact law with the P-W parameter set (an analytic
// wall may instead take that set without sliding and rolling friction, a frictionless face):
// analytic walls (one history per particle and wall) and triangle meshes (MeshWall::kMaxContacts
// slots per particle and mesh, each a normal and a history, matched by normal from step to step).
// Each contact touches only its own particle, so threads may run their own rows at once. The
// law runs over batches of closed contacts (wall_contact_batch.hpp), as in the pair loop.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "fullsim/dem/force_kernel.hpp"
#include "fullsim/dem/wall_contact_batch.hpp"
#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

// Zeroes an open contact's history; reads first, so that the many open entries of a dense
// list are not written (and their cache lines not dirtied) every step. A law whose first slot is
// non-zero once the contact has touched (Law::kFirstSlotMarksUse: the hysteretic laws' largest
// overlap) is read at that slot only.
template <class Law>
inline void clear_history(double* h) {
  constexpr std::size_t kHistory = Law::kHistorySize;
  if constexpr (Law::kFirstSlotMarksUse) {
    if (h[0] != 0.0) std::fill(h, h + kHistory, 0.0);
  } else if constexpr (kHistory > 0) {
    for (std::size_t k = 0; k < kHistory; ++k)
      if (h[k] != 0.0) {
        std::fill(h, h + kHistory, 0.0);
        return;
      }
  }
}

template <class Law>
class WallContactForces {
 public:
  static constexpr std::size_t kHistory = Law::kHistorySize;
  using Batch = WallContactBatch<kHistory>;

  // One thread's closed contacts waiting for the law: a batch per parameter set (the P-W set,
  // and the frictionless faces' set) and the order in which the contacts were found.
  struct Scratch {
    std::array<Batch, 2> batch;  // [0]: the P-W set, [1]: without friction
    std::array<std::uint32_t, 2 * Batch::kSize> particle;
    std::array<std::uint8_t, 2 * Batch::kSize> set, lane;
    std::size_t count = 0;
  };

  explicit WallContactForces(const DemContactParameters& particle_wall)
      : law_(particle_wall), frictionless_law_(without_friction(particle_wall)) {}

  // The particle-wall contacts of the particles in slots [begin, end), each touching only its
  // own particle (so a thread may run its own rows, with its own `scratch`, while another runs
  // its own). The closed contacts are gathered into batches, the law runs over each batch as one
  // vector loop, and each particle takes its contacts' forces in the order they were found.
  DeepestOverlap rows(ForceContext& c, std::size_t begin, std::size_t end, Scratch& scratch) {
    ParticleStore& p = c.particles;
    const std::size_t walls = c.walls.size();
    const std::size_t meshes = c.meshes.size();
    // Per particle: walls x history, then per mesh kMaxContacts slots of (normal, history);
    // a slot's normal (zero when free) matches it to the same contact at the next step.
    constexpr std::size_t kSlot = 3 + kHistory;
    constexpr int kSlots = MeshWall::kMaxContacts;
    const std::size_t stride = walls * kHistory + meshes * kSlots * kSlot;
    double* history = p.wall_history.data();
    const int lane_bits = std::min(c.max_lane_bits, lane_bits_available());
    DeepestOverlap worst;
    scratch.count = 0;
    for (Batch& b : scratch.batch) b.count = 0;
    // Queues a closed contact of particle i with parameter set `set` (0 or 1).
    auto queue = [&](std::size_t i, int set, double gap, const Vec3& normal,
                     const Vec3& surface_velocity, const Vec3& wall_spin, double* h) {
      Batch& b = scratch.batch[static_cast<std::size_t>(set)];
      if (b.count == Batch::kSize) run(scratch, p, c.dt, lane_bits, worst);
      const std::size_t k = b.count++;
      b.set_contact(k, gap, normal, p.radius[i], p.velocity[i] - surface_velocity,
                    p.angular_velocity[i], wall_spin, p.mass[i], p.inertia[i], h);
      const std::size_t o = scratch.count++;
      scratch.particle[o] = static_cast<std::uint32_t>(i);
      scratch.set[o] = static_cast<std::uint8_t>(set);
      scratch.lane[o] = static_cast<std::uint8_t>(k);
    };
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3 xi = p.position[i];
      const double ri = p.radius[i];
      const std::uint64_t reach = c.wall_reach ? c.wall_reach[i] : ~std::uint64_t{0};
      for (std::size_t k = 0; k < walls; ++k) {
        if (!in_reach(reach, k)) continue;  // no contact, history already zero
        const Wall& wall = c.walls[k];
        double* h = history + i * stride + k * kHistory;
        const WallTouch touch = wall.touch(xi);
        const double overlap = ri - touch.gap;
        if (!(overlap > 0.0) || !wall.active(c.time)) {
          clear_history<Law>(h);
          continue;
        }
        queue(i, wall.contact_set() == WallContactSet::frictionless ? 1 : 0, touch.gap,
              touch.normal, wall.surface_velocity(xi - touch.gap * touch.normal),
              wall.angular_velocity(), h);
      }
      for (std::size_t m = 0; m < meshes; ++m) {
        if (!in_reach(reach, walls + m)) continue;  // no contact, slots already free
        const MeshWall& mesh = c.meshes[m];
        double* slots = history + i * stride + walls * kHistory + m * kSlots * kSlot;
        std::array<MeshTouch, kSlots> touch;
        const int count = mesh.active(c.time) ? mesh.touches(xi, ri, touch) : 0;
        // Each contact takes the slot whose stored normal is closest to its own (a contact
        // sliding onto the next triangle keeps its history); the others start from zero.
        std::array<int, kSlots> slot_of;
        std::array<bool, kSlots> taken{};
        for (int q = 0; q < count; ++q) {
          slot_of[q] = -1;
          double best = 0.8;  // within about 37 degrees
          for (int s = 0; s < kSlots; ++s) {
            if (taken[s]) continue;
            const double* sn = slots + s * kSlot;
            const double d = dot(touch[q].normal, Vec3(sn[0], sn[1], sn[2]));
            if (d > best) {
              best = d;
              slot_of[q] = s;
            }
          }
          if (slot_of[q] >= 0) taken[slot_of[q]] = true;
        }
        for (int s = 0; s < kSlots; ++s)
          if (!taken[s]) clear_slot(slots + s * kSlot);
        for (int q = 0; q < count; ++q) {
          if (slot_of[q] < 0)
            for (int s = 0; s < kSlots; ++s)
              if (!taken[s]) {
                taken[s] = true;
                slot_of[q] = s;
                break;
              }
          double* slot = slots + slot_of[q] * kSlot;
          slot[0] = touch[q].normal.x();
          slot[1] = touch[q].normal.y();
          slot[2] = touch[q].normal.z();
          queue(i, 0, touch[q].gap, touch[q].normal, mesh.surface_velocity(touch[q].point),
                mesh.angular_velocity(), slot + 3);
        }
      }
    }
    run(scratch, p, c.dt, lane_bits, worst);
    return worst;
  }

 private:
  // Whether wall (or mesh) `k` may touch a particle with this reach mask (WallReach: beyond 64
  // walls every wall is in reach).
  static bool in_reach(std::uint64_t reach, std::size_t k) {
    return k >= 64 || ((reach >> k) & 1u) != 0;
  }
  // The P-W set with no sliding and no rolling friction (normal law and damping kept).
  static DemContactParameters without_friction(DemContactParameters set) {
    set.friction = 0.0;
    set.rolling_friction = 0.0;
    return set;
  }

  // Runs the law over the queued contacts and adds their forces and torques to their particles
  // in the order the contacts were found; watches the deepest.
  void run(Scratch& s, ParticleStore& p, double dt, int lane_bits, DeepestOverlap& worst) const {
    if (s.batch[0].count > 0) s.batch[0].evaluate_with(lane_bits, law_, dt);
    if (s.batch[1].count > 0) s.batch[1].evaluate_with(lane_bits, frictionless_law_, dt);
    for (std::size_t o = 0; o < s.count; ++o) {
      const Batch& b = s.batch[s.set[o]];
      const std::size_t k = s.lane[o], i = s.particle[o];
      b.store_history(k);
      p.force[i] += Vec3(b.fx[k], b.fy[k], b.fz[k]);
      p.torque[i] += Vec3(b.tx[k], b.ty[k], b.tz[k]);
      const double ratio = b.overlap_ratio(k);
      if (ratio > worst.ratio) worst = {ratio, i, true};
    }
    s.count = 0;
    for (Batch& b : s.batch) b.count = 0;
  }
  // Frees a mesh contact slot (normal and history).
  static void clear_slot(double* s) {
    for (std::size_t k = 0; k < 3 + kHistory; ++k)
      if (s[k] != 0.0) {
        std::fill(s, s + 3 + kHistory, 0.0);
        return;
      }
  }

  Law law_;               // the P-W set
  Law frictionless_law_;  // the P-W set without sliding and rolling friction
};

}  // namespace feedflow
