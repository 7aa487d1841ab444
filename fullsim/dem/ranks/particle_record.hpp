#pragma once
// One whole particle as a run of doubles (what a rank taking it over needs): id, position,
// velocity, angular velocity, force, torque, radius, mass, inertia, layer and its wall-contact
// history. Migration and the gathered checkpoint send particles this way.
#include <cstddef>
#include <vector>

#include "fullsim/dem/particle_store.hpp"

namespace feedflow {

inline void put_vec3(std::vector<double>& out, const Vec3& v) {
  out.insert(out.end(), {v.x(), v.y(), v.z()});
}

inline Vec3 take_vec3(const double*& in) {
  const Vec3 v(in[0], in[1], in[2]);
  in += 3;
  return v;
}

// Appends slot k of the store.
void put_particle(std::vector<double>& out, const ParticleStore& p, std::size_t k);
// Adds the particle read at `in` behind the store's last slot; `in` moves past it.
void take_particle(const double*& in, ParticleStore& p);

}  // namespace feedflow
