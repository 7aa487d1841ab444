#include "fullsim/dem/particle_store.hpp"

#include <algorithm>
#include <numbers>

namespace feedflow {
namespace {

template <class T>
void permute_field(std::vector<T>& field, const std::vector<std::size_t>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = field[order[k]];
  field.swap(out);
}

template <class T>
void compact_field(std::vector<T>& field, const std::vector<char>& flagged) {
  std::size_t w = 0;
  for (std::size_t k = 0; k < field.size(); ++k)
    if (!flagged[k]) field[w++] = field[k];
  field.resize(w);
}

}  // namespace

std::uint32_t ParticleStore::add(const Vec3& x, double r, double density, double tag,
                                 const Vec3& v) {
  const double m = sphere_mass(density, r);
  position.push_back(x);
  velocity.push_back(v);
  angular_velocity.push_back(Vec3::Zero());
  force.push_back(Vec3::Zero());
  torque.push_back(Vec3::Zero());
  radius.push_back(r);
  mass.push_back(m);
  inertia.push_back(0.4 * m * r * r);
  layer.push_back(tag);
  id.push_back(next_id_);
  wall_history.resize(wall_history.size() + wall_stride_, 0.0);
  return next_id_++;
}

void ParticleStore::set_wall_history_stride(std::size_t stride) {
  wall_stride_ = stride;
  wall_history.assign(size() * stride, 0.0);
}

void ParticleStore::permute(const std::vector<std::size_t>& order) {
  permute_field(position, order);
  permute_field(velocity, order);
  permute_field(angular_velocity, order);
  permute_field(force, order);
  permute_field(torque, order);
  permute_field(radius, order);
  permute_field(mass, order);
  permute_field(inertia, order);
  permute_field(layer, order);
  permute_field(id, order);
  if (wall_stride_ > 0) {
    std::vector<double> out(wall_history.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      std::copy_n(wall_history.begin() + static_cast<std::ptrdiff_t>(order[k] * wall_stride_),
                  wall_stride_, out.begin() + static_cast<std::ptrdiff_t>(k * wall_stride_));
    wall_history.swap(out);
  }
}

void ParticleStore::remove_flagged(const std::vector<char>& flagged) {
  if (wall_stride_ > 0) {
    std::size_t w = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      if (flagged[k]) continue;
      std::copy_n(wall_history.begin() + static_cast<std::ptrdiff_t>(k * wall_stride_),
                  wall_stride_, wall_history.begin() + static_cast<std::ptrdiff_t>(w * wall_stride_));
      ++w;
    }
    wall_history.resize(w * wall_stride_);
  }
  compact_field(position, flagged);
  compact_field(velocity, flagged);
  compact_field(angular_velocity, flagged);
  compact_field(force, flagged);
  compact_field(torque, flagged);
  compact_field(radius, flagged);
  compact_field(mass, flagged);
  compact_field(inertia, flagged);
  compact_field(layer, flagged);
  compact_field(id, flagged);
}

void ParticleStore::resize(std::size_t n) {
  position.resize(n, Vec3::Zero());
  velocity.resize(n, Vec3::Zero());
  angular_velocity.resize(n, Vec3::Zero());
  force.resize(n, Vec3::Zero());
  torque.resize(n, Vec3::Zero());
  radius.resize(n, 0.0);
  mass.resize(n, 0.0);
  inertia.resize(n, 0.0);
  layer.resize(n, 0.0);
  id.resize(n, 0);
  wall_history.resize(n * wall_stride_, 0.0);
}

double ParticleStore::total_mass(std::size_t n) const {
  double m = 0.0;
  for (std::size_t k = 0; k < std::min(n, size()); ++k) m += mass[k];
  return m;
}

double ParticleStore::kinetic_energy(std::size_t n) const {
  double e = 0.0;
  for (std::size_t k = 0; k < std::min(n, size()); ++k)
    e += 0.5 * mass[k] * velocity[k].squaredNorm() +
         0.5 * inertia[k] * angular_velocity[k].squaredNorm();
  return e;
}

double ParticleStore::max_radius() const {
  double r = 0.0;
  for (double ri : radius) r = std::max(r, ri);
  return r;
}

}  // namespace feedflow
