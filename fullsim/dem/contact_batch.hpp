#pragma once
// A batch of touching pairs of the pair loop, laid out as structure of arrays: one lane per
// contact, so that the contact kinematics and the composed law run over the batch as one loop
// the compiler vectorises (the square roots and divisions of several contacts in one
// instruction). The pair loop fills each lane's separation, velocities and contact history,
// `evaluate` takes the kinematics, runs the law and leaves the force and both torques beside
// them, and the pair loop then adds them in lane order (the same sums, in the same order, as
// one contact at a time).
#include <cstddef>
#include <cmath>
#include <cstdint>

#include "fullsim/dem/lane_widths.hpp"
#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

template <std::size_t kHistory>
struct ContactBatch : LaneWidths<ContactBatch<kHistory>> {
  static constexpr std::size_t kSize = 32;
  // What the first pass of the pair loop gives (set_pair).
  alignas(64) double dx[kSize], dy[kSize], dz[kSize], r2[kSize];
  alignas(64) double radius_i[kSize], radius_j[kSize];
  alignas(64) double vrx[kSize], vry[kSize], vrz[kSize];
  alignas(64) double wix[kSize], wiy[kSize], wiz[kSize], wjx[kSize], wjy[kSize], wjz[kSize];
  alignas(64) double radius[kSize], mass[kSize], inertia[kSize];  // R*, m*, I*
  alignas(64) double overlap[kSize];  // taken in the vector loop (the deepest is watched)
  // The contact history, slot by slot (read before the law, written back after it).
  alignas(64) double history[kHistory > 0 ? kHistory : 1][kSize];
  // Outputs: the contact force on body i (body j takes its opposite) and the torques on both.
  alignas(64) double fx[kSize], fy[kSize], fz[kSize];
  alignas(64) double tix[kSize], tiy[kSize], tiz[kSize];
  alignas(64) double tjx[kSize], tjy[kSize], tjz[kSize];
  std::uint32_t i[kSize], j[kSize], entry[kSize];
  std::size_t count = 0;

  // What the pair loop's first pass leaves for lane k: the separation d = x_i - x_j (minimum
  // image) with |d|^2 < (r_i + r_j)^2, the radii, v_i - v_j and both spins. The square root,
  // the normal and the contact-point velocity are taken in the vector loop.
  void set_pair(std::size_t k, const Vec3& d, double d2, double ri, double rj, const Vec3& vr,
                const Vec3& wi, const Vec3& wj) {
    dx[k] = d.x();
    dy[k] = d.y();
    dz[k] = d.z();
    r2[k] = d2;
    radius_i[k] = ri;
    radius_j[k] = rj;
    vrx[k] = vr.x();
    vry[k] = vr.y();
    vrz[k] = vr.z();
    wix[k] = wi.x();
    wiy[k] = wi.y();
    wiz[k] = wi.z();
    wjx[k] = wj.x();
    wjy[k] = wj.y();
    wjz[k] = wj.z();
  }

 private:
  friend struct LaneWidths<ContactBatch>;
  // The batch's one loop over lanes [0, count), all of them touching pairs, run by
  // LaneWidths' evaluate variants (lane_widths.hpp).
  template <class Law>
  [[gnu::always_inline]] inline void lanes(const Law& law, double dt) {
    const std::size_t n = count;
    // No aliasing between the lanes' arrays; the law is written with selects, not branches,
    // so g++ vectorises this loop (with Eigen's own SSE code off in this translation unit).
#pragma GCC ivdep
    for (std::size_t k = 0; k < n; ++k) {
      // Kinematics (models.md 4.1): overlap, unit normal from j to i, the distances from the
      // centres to the contact point, normal and tangential velocity of the contact point.
      const double r = std::sqrt(r2[k]);
      ContactInput in;
      in.overlap = (radius_i[k] + radius_j[k]) - r;
      in.normal = Vec3(dx[k], dy[k], dz[k]) * (1.0 / r);
      const double c_i = radius_i[k] - 0.5 * in.overlap;
      const double c_j = radius_j[k] - 0.5 * in.overlap;
      Vec3 vr(vrx[k], vry[k], vrz[k]);
      Vec3 wi(wix[k], wiy[k], wiz[k]), wj(wjx[k], wjy[k], wjz[k]);
      in.normal_velocity = dot(vr, in.normal);
      in.tangential_velocity = vr - in.normal_velocity * in.normal +
                               in.normal.cross(c_i * wi + c_j * wj);
      in.relative_angular_velocity = wi - wj;
      overlap[k] = in.overlap;
      in.effective_radius = radius[k];
      in.effective_mass = mass[k];
      in.effective_inertia = inertia[k];
      in.dt = dt;
      typename Law::History h;
      for (std::size_t q = 0; q < kHistory; ++q) h[q] = history[q][k];
      ContactOutput out = law.evaluate_touching(in, h);  // not const: see evaluate_touching
      for (std::size_t q = 0; q < kHistory; ++q) history[q][k] = h[q];
      // F = F_n n + F_t on i; the tangential force acts at the contact point, c_i from i's
      // centre and c_j from j's; the rolling torque acts on i and reversed on j.
      Vec3 f = out.normal_force * in.normal + out.tangential_force;
      Vec3 lever = in.normal.cross(out.tangential_force);
      Vec3 torque_i = out.rolling_torque - c_i * lever;
      Vec3 torque_j = -(out.rolling_torque + c_j * lever);
      fx[k] = f.x();
      fy[k] = f.y();
      fz[k] = f.z();
      tix[k] = torque_i.x();
      tiy[k] = torque_i.y();
      tiz[k] = torque_i.z();
      tjx[k] = torque_j.x();
      tjy[k] = torque_j.y();
      tjz[k] = torque_j.z();
    }
  }
};

}  // namespace feedflow
