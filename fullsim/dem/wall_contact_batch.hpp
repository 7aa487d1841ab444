#pragma once
// A batch of closed particle-wall contacts, laid out as structure of arrays like the pair loop's
// ContactBatch: one lane per contact, so the kinematics and the composed law (with one P-W
// parameter set) run over the batch as one loop the compiler vectorises. The wall loop fills a
// lane with the touch (gap and unit normal from the wall to the particle), the particle's
// radius, velocity relative to the wall's surface, spins, mass, inertia and history; `evaluate`
// leaves the force and torque on the particle beside them, and the wall loop adds them in the
// order the contacts were found (the same sums as one contact at a time).
#include <cstddef>
#include <cstdint>

#include "fullsim/dem/lane_widths.hpp"
#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

template <std::size_t kHistory>
struct WallContactBatch : LaneWidths<WallContactBatch<kHistory>> {
  static constexpr std::size_t kSize = 32;
  alignas(64) double nx[kSize], ny[kSize], nz[kSize], gap[kSize], radius[kSize];
  alignas(64) double vrx[kSize], vry[kSize], vrz[kSize];        // v_i - wall surface velocity
  alignas(64) double wx[kSize], wy[kSize], wz[kSize];           // the particle's spin
  alignas(64) double wwx[kSize], wwy[kSize], wwz[kSize];        // the wall's angular velocity
  alignas(64) double mass[kSize], inertia[kSize];
  alignas(64) double history[kHistory > 0 ? kHistory : 1][kSize];
  // Outputs: the force and torque on the particle.
  alignas(64) double fx[kSize], fy[kSize], fz[kSize];
  alignas(64) double tx[kSize], ty[kSize], tz[kSize];
  double* stored[kSize];  // where each lane's history lives between steps
  std::size_t count = 0;

  // Lane k: a sphere of radius r with centre at `gap` from the wall along `normal` (gap < r),
  // moving at `relative_velocity` to the wall's surface there, with spin `w` and history `h`
  // (kHistory doubles, copied in now and back by `store_history`).
  void set_contact(std::size_t k, double contact_gap, const Vec3& normal, double r,
                   const Vec3& relative_velocity, const Vec3& w, const Vec3& wall_spin, double m,
                   double moment, double* h) {
    nx[k] = normal.x();
    ny[k] = normal.y();
    nz[k] = normal.z();
    gap[k] = contact_gap;
    radius[k] = r;
    vrx[k] = relative_velocity.x();
    vry[k] = relative_velocity.y();
    vrz[k] = relative_velocity.z();
    wx[k] = w.x();
    wy[k] = w.y();
    wz[k] = w.z();
    wwx[k] = wall_spin.x();
    wwy[k] = wall_spin.y();
    wwz[k] = wall_spin.z();
    mass[k] = m;
    inertia[k] = moment;
    stored[k] = h;
    for (std::size_t q = 0; q < kHistory; ++q) history[q][k] = h[q];
  }
  // Writes lane k's history back where it lives.
  void store_history(std::size_t k) const {
    for (std::size_t q = 0; q < kHistory; ++q) stored[k][q] = history[q][k];
  }
  // Lane k's overlap over the radius (the deepest contact is watched).
  double overlap_ratio(std::size_t k) const { return (radius[k] - gap[k]) / radius[k]; }

 private:
  friend struct LaneWidths<WallContactBatch>;
  // The batch's one loop over lanes [0, count), run by LaneWidths' evaluate variants
  // (lane_widths.hpp).
  template <class Law>
  [[gnu::always_inline]] inline void lanes(const Law& law, double dt) {
    const std::size_t n = count;
#pragma GCC ivdep
    for (std::size_t k = 0; k < n; ++k) {
      // Kinematics (models.md 4.1) with the wall as the second body: the contact point lies
      // `gap` from the centre, the wall adds no radius, mass or inertia.
      const double r = radius[k];
      ContactInput in;
      in.overlap = r - gap[k];
      in.normal = Vec3(nx[k], ny[k], nz[k]);
      const double c_i = r - in.overlap;
      Vec3 vr(vrx[k], vry[k], vrz[k]);
      Vec3 w(wx[k], wy[k], wz[k]);
      in.normal_velocity = dot(vr, in.normal);
      in.tangential_velocity = vr - in.normal_velocity * in.normal + in.normal.cross(c_i * w);
      in.relative_angular_velocity = w - Vec3(wwx[k], wwy[k], wwz[k]);
      in.effective_radius = r;
      in.effective_mass = mass[k];
      in.effective_inertia = inertia[k];
      in.dt = dt;
      typename Law::History h;
      for (std::size_t q = 0; q < kHistory; ++q) h[q] = history[q][k];
      ContactOutput out = law.evaluate_touching(in, h);  // not const: see evaluate_touching
      for (std::size_t q = 0; q < kHistory; ++q) history[q][k] = h[q];
      Vec3 f = out.normal_force * in.normal + out.tangential_force;
      Vec3 t = out.rolling_torque - c_i * in.normal.cross(out.tangential_force);
      fx[k] = f.x();
      fy[k] = f.y();
      fz[k] = f.z();
      tx[k] = t.x();
      ty[k] = t.y();
      tz[k] = t.z();
    }
  }
};

}  // namespace feedflow
