#include "fullsim/dem/ranks/particle_record.hpp"

#include <algorithm>

namespace feedflow {

void put_particle(std::vector<double>& out, const ParticleStore& p, std::size_t k) {
  const std::size_t stride = p.wall_history_stride();
  out.push_back(static_cast<double>(p.id[k]));
  for (const Vec3* v : {&p.position[k], &p.velocity[k], &p.angular_velocity[k], &p.force[k],
                        &p.torque[k]})
    put_vec3(out, *v);
  out.insert(out.end(), {p.radius[k], p.mass[k], p.inertia[k], p.layer[k]});
  const auto from = p.wall_history.begin() + static_cast<std::ptrdiff_t>(k * stride);
  out.insert(out.end(), from, from + static_cast<std::ptrdiff_t>(stride));
}

void take_particle(const double*& in, ParticleStore& p) {
  const std::size_t stride = p.wall_history_stride();
  const std::size_t k = p.size();
  p.resize(k + 1);
  p.id[k] = static_cast<std::uint32_t>(*in++);
  p.position[k] = take_vec3(in);
  p.velocity[k] = take_vec3(in);
  p.angular_velocity[k] = take_vec3(in);
  p.force[k] = take_vec3(in);
  p.torque[k] = take_vec3(in);
  p.radius[k] = *in++;
  p.mass[k] = *in++;
  p.inertia[k] = *in++;
  p.layer[k] = *in++;
  std::copy_n(in, stride, p.wall_history.begin() + static_cast<std::ptrdiff_t>(k * stride));
  in += stride;
}

}  // namespace feedflow
