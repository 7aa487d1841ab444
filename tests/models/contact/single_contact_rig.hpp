#pragma once
// Test support: spheres, the contact kinematics of models.md 4.1 for a sphere pair or a sphere
// on a plane, and a velocity-Verlet step in LIGGGHTS' order (half kick, drift, forces from the
// half-step velocities, half kick; models.md 4.5). Tiny and single-contact; not the engine.
#include <cmath>
#include <numbers>

#include "models/contact/contact_kinematics.hpp"

namespace feedflow::rig {

struct Sphere {
  double radius = 0.0;
  double mass = 0.0;
  double inertia = 0.0;
  Vec3 x = Vec3::Zero();
  Vec3 v = Vec3::Zero();
  Vec3 w = Vec3::Zero();
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
  bool frozen = false;           // never moves (LIGGGHTS `fix freeze`)
  bool rotation_locked = false;  // a sphere that cannot roll: behaves as a sliding block
};

inline Sphere make_sphere(double radius, double density) {
  Sphere s;
  s.radius = radius;
  s.mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  s.inertia = 0.4 * s.mass * radius * radius;
  return s;
}

// Contact of sphere i with sphere j (n from j to i); m* = m_i when j is frozen.
inline ContactInput pair_contact(const Sphere& i, const Sphere& j, double dt) {
  ContactInput in;
  const Vec3 d = i.x - j.x;
  const double r = d.norm();
  in.overlap = i.radius + j.radius - r;
  in.normal = d / r;
  const Vec3 vr = i.v - j.v;
  in.normal_velocity = vr.dot(in.normal);
  const double ri = i.radius - in.overlap / 2, rj = j.radius - in.overlap / 2;
  in.tangential_velocity =
      vr - in.normal_velocity * in.normal + in.normal.cross(ri * i.w + rj * j.w);
  in.relative_angular_velocity = i.w - j.w;
  in.effective_radius = i.radius * j.radius / (i.radius + j.radius);
  in.effective_mass = j.frozen ? i.mass : i.mass * j.mass / (i.mass + j.mass);
  in.effective_inertia = j.frozen ? i.inertia : i.inertia * j.inertia / (i.inertia + j.inertia);
  in.dt = dt;
  return in;
}

// Contact of sphere i with a fixed plane through `point` with unit normal `normal` (towards i).
inline ContactInput plane_contact(const Sphere& i, const Vec3& point, const Vec3& normal,
                                  double dt) {
  ContactInput in;
  in.overlap = i.radius - (i.x - point).dot(normal);
  in.normal = normal;
  in.normal_velocity = i.v.dot(normal);
  const double ri = i.radius - in.overlap;
  in.tangential_velocity = i.v - in.normal_velocity * normal + normal.cross(ri * i.w);
  in.relative_angular_velocity = i.w;
  in.effective_radius = i.radius;
  in.effective_mass = i.mass;
  in.effective_inertia = i.inertia;
  in.dt = dt;
  return in;
}

// Adds a contact's force and torques to i (and the opposites to j if given).
inline void apply(const ContactInput& in, const ContactOutput& out, Sphere& i, Sphere* j,
                  double contact_radius_i, double contact_radius_j) {
  const Vec3 f = out.normal_force * in.normal + out.tangential_force;
  const Vec3 lever = in.normal.cross(out.tangential_force);
  i.force += f;
  i.torque += -contact_radius_i * lever + out.rolling_torque;
  if (j) {
    j->force -= f;
    j->torque += -contact_radius_j * lever - out.rolling_torque;
  }
}

inline void half_kick(Sphere& s, double dt) {
  if (s.frozen) return;
  s.v += 0.5 * dt * s.force / s.mass;
  if (!s.rotation_locked) s.w += 0.5 * dt * s.torque / s.inertia;
}

// One velocity-Verlet step; `forces()` fills force and torque (they are zeroed before).
template <class Forces>
void verlet_step(Sphere& s, double dt, Forces&& forces) {
  half_kick(s, dt);
  if (!s.frozen) s.x += dt * s.v;
  s.force.setZero();
  s.torque.setZero();
  forces();
  half_kick(s, dt);
}

}  // namespace feedflow::rig
