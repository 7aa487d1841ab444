#pragma once
// The particle-wall contacts of one composed contact law with the P-W parameter set (an analytic
// wall may instead take that set without sliding and rolling friction, a frictionless face):
// analytic walls (one history per particle and wall) and triangle meshes (MeshWall::kMaxContacts
// slots per particle and mesh, each a normal and a history, matched by normal from step to step).
// Each contact touches only its own particle, so threads may run their own rows at once.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fullsim/dem/force_kernel.hpp"
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
  using History = typename Law::History;
  static constexpr std::size_t kHistory = Law::kHistorySize;

  explicit WallContactForces(const DemContactParameters& particle_wall)
      : law_(particle_wall), frictionless_law_(without_friction(particle_wall)) {}

  // The particle-wall contacts of the particles in slots [begin, end), each touching only its
  // own particle (so a thread may run its own rows while another runs its own).
  DeepestOverlap rows(ForceContext& c, std::size_t begin, std::size_t end) {
    ParticleStore& p = c.particles;
    const std::size_t walls = c.walls.size();
    const std::size_t meshes = c.meshes.size();
    // Per particle: walls x history, then per mesh kMaxContacts slots of (normal, history);
    // a slot's normal (zero when free) matches it to the same contact at the next step.
    constexpr std::size_t kSlot = 3 + kHistory;
    constexpr int kSlots = MeshWall::kMaxContacts;
    const std::size_t stride = walls * kHistory + meshes * kSlots * kSlot;
    double* history = p.wall_history.data();
    DeepestOverlap worst;
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
        const Vec3 surface_velocity = wall.surface_velocity(xi - touch.gap * touch.normal);
        const Law& law =
            wall.contact_set() == WallContactSet::frictionless ? frictionless_law_ : law_;
        const double ratio = apply_wall_contact(law, p, i, touch.gap, touch.normal,
                                                surface_velocity, wall.angular_velocity(), c.dt, h);
        if (ratio > worst.ratio) worst = {ratio, i, true};
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
          const double ratio = apply_wall_contact(law_, p, i, touch[q].gap, touch[q].normal,
                                                  mesh.surface_velocity(touch[q].point),
                                                  mesh.angular_velocity(), c.dt, slot + 3);
          if (ratio > worst.ratio) worst = {ratio, i, true};
        }
      }
    }
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

  // One particle-wall contact with `law` (its parameter set): adds its force and torque to
  // particle i and returns the overlap over the radius.
  double apply_wall_contact(const Law& law, ParticleStore& p, std::size_t i, double gap,
                            const Vec3& normal, const Vec3& surface_velocity,
                            const Vec3& wall_angular_velocity, double dt, double* h) {
    const double ri = p.radius[i];
    const double overlap = ri - gap;
    ContactInput in;
    in.overlap = overlap;
    in.normal = normal;
    const double ci = ri - overlap;
    const Vec3 vr = p.velocity[i] - surface_velocity;
    in.normal_velocity = dot(vr, in.normal);
    in.tangential_velocity =
        vr - in.normal_velocity * in.normal + in.normal.cross(ci * p.angular_velocity[i]);
    in.relative_angular_velocity = p.angular_velocity[i] - wall_angular_velocity;
    in.effective_radius = ri;
    in.effective_mass = p.mass[i];
    in.effective_inertia = p.inertia[i];
    in.dt = dt;
    History hist;
    if constexpr (kHistory > 0) std::memcpy(hist.data(), h, sizeof(History));
    const ContactOutput out = law.evaluate(in, hist);
    if constexpr (kHistory > 0) std::memcpy(h, hist.data(), sizeof(History));
    p.force[i] += out.normal_force * in.normal + out.tangential_force;
    p.torque[i] += out.rolling_torque - ci * in.normal.cross(out.tangential_force);
    return overlap / ri;
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
