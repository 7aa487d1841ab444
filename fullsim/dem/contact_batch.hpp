#pragma once
// A batch of touching pairs of the pair loop, laid out as structure of arrays: one lane per
// contact, so that the composed law runs over the batch as one loop the compiler vectorises
// (the square roots and divisions of several contacts in one instruction). The pair loop
// fills the kinematics and the contact histories, `evaluate` runs the law on every lane and
// leaves the outputs beside them, and the pair loop then adds the forces in lane order (the
// same sums, in the same order, as one contact at a time).
#include <cstddef>
#include <cstdint>

#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

template <std::size_t kHistory>
struct ContactBatch {
  static constexpr std::size_t kSize = 32;
  // Kinematics of each lane (models.md 4.1; as ContactInput).
  alignas(64) double overlap[kSize];
  alignas(64) double nx[kSize], ny[kSize], nz[kSize];   // unit normal from j to i
  alignas(64) double vn[kSize];                         // normal velocity
  alignas(64) double vtx[kSize], vty[kSize], vtz[kSize];  // tangential velocity
  alignas(64) double wx[kSize], wy[kSize], wz[kSize];   // relative angular velocity
  alignas(64) double radius[kSize], mass[kSize], inertia[kSize];  // R*, m*, I*
  alignas(64) double ci[kSize], cj[kSize];  // distances from the centres to the contact point
  // The contact history, slot by slot (read before the law, written back after it).
  alignas(64) double history[kHistory > 0 ? kHistory : 1][kSize];
  // Outputs of the law on body i.
  alignas(64) double fn[kSize];
  alignas(64) double ftx[kSize], fty[kSize], ftz[kSize];  // tangential force
  alignas(64) double mx[kSize], my[kSize], mz[kSize];     // rolling torque
  std::uint32_t i[kSize], j[kSize], entry[kSize];
  std::size_t count = 0;

  // Runs `law` (a ContactLaw) on lanes [0, count), all of them touching pairs, with the vector
  // width of any x86-64 (two lanes); `evaluate_wide` is the same loop for AVX2 (four lanes),
  // chosen at run time when the processor has it (`wide_lanes_available`, force_kernel.hpp).
  // The two give the same results bit for bit: each lane's arithmetic is the scalar one, and
  // the translation unit is built without floating-point contraction (fullsim/CMakeLists.txt).
  template <class Law>
  [[gnu::noinline, gnu::flatten]] void evaluate(const Law& law, double dt) {
    lanes(law, dt);
  }
#if defined(__x86_64__)
  template <class Law>
  [[gnu::noinline, gnu::flatten, gnu::target("avx2,fma")]] void evaluate_wide(const Law& law,
                                                                             double dt) {
    lanes(law, dt);
  }
#endif

 private:
  template <class Law>
  [[gnu::always_inline]] inline void lanes(const Law& law, double dt) {
    const std::size_t n = count;
    // No aliasing between the lanes' arrays; the law is written with selects, not branches,
    // so g++ vectorises this loop (with Eigen's own SSE code off in this translation unit).
#pragma GCC ivdep
    for (std::size_t k = 0; k < n; ++k) {
      ContactInput in;
      in.overlap = overlap[k];
      in.normal = Vec3(nx[k], ny[k], nz[k]);
      in.normal_velocity = vn[k];
      in.tangential_velocity = Vec3(vtx[k], vty[k], vtz[k]);
      in.relative_angular_velocity = Vec3(wx[k], wy[k], wz[k]);
      in.effective_radius = radius[k];
      in.effective_mass = mass[k];
      in.effective_inertia = inertia[k];
      in.dt = dt;
      typename Law::History h;
      for (std::size_t q = 0; q < kHistory; ++q) h[q] = history[q][k];
      ContactOutput out = law.evaluate_touching(in, h);  // not const: see evaluate_touching
      for (std::size_t q = 0; q < kHistory; ++q) history[q][k] = h[q];
      fn[k] = out.normal_force;
      ftx[k] = out.tangential_force.x();
      fty[k] = out.tangential_force.y();
      ftz[k] = out.tangential_force.z();
      mx[k] = out.rolling_torque.x();
      my[k] = out.rolling_torque.y();
      mz[k] = out.rolling_torque.z();
    }
  }
};

}  // namespace feedflow
