#pragma once
// The particles of a DEM run as a structure of arrays (one array per field, indexed by the
// particle's current slot). Slots change when the store is re-sorted or particles are removed;
// the id of a particle never changes. The per-particle wall-contact history (one row of
// walls x history doubles per particle) moves with its particle.
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

#include "models/contact/contact_kinematics.hpp"

namespace feedflow {

class ParticleStore {
 public:
  std::vector<Vec3> position;          // [m]
  std::vector<Vec3> velocity;          // [m/s]
  std::vector<Vec3> angular_velocity;  // [rad/s]
  std::vector<Vec3> force;             // [N]
  std::vector<Vec3> torque;            // [N m]
  std::vector<double> radius;          // [m]
  std::vector<double> mass;            // [kg]
  std::vector<double> inertia;         // (2/5) m R^2 [kg m^2]
  std::vector<double> layer;           // a per-particle scalar, e.g. the initial layer
  std::vector<std::uint32_t> id;       // never changes
  std::vector<double> wall_history;    // wall_history_stride doubles per particle

  std::size_t size() const { return position.size(); }

  // The mass of a solid sphere as add() books it [kg].
  static double sphere_mass(double density, double radius) {
    return density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  }
  // Adds a solid sphere; returns its id.
  std::uint32_t add(const Vec3& x, double radius, double density, double layer = 0.0,
                    const Vec3& v = Vec3::Zero());

  // Sets the doubles of wall-contact history per particle (zeroes them).
  void set_wall_history_stride(std::size_t stride);
  std::size_t wall_history_stride() const { return wall_stride_; }
  // The id the next added particle gets; set when restoring a checkpoint.
  std::uint32_t next_id() const { return next_id_; }
  void set_next_id(std::uint32_t id) { next_id_ = id; }

  // Reorders the slots: new slot k holds the particle of old slot order[k].
  void permute(const std::vector<std::size_t>& order);
  // Removes the particles whose flag is set, keeping the order of the others.
  void remove_flagged(const std::vector<char>& flagged);
  // Keeps the first n slots, or adds zeroed ones up to n (a rank's ghost copies are added and
  // dropped this way behind its own particles).
  void resize(std::size_t n);

  // Of the first n slots (all by default: a rank's own particles are its first slots).
  double total_mass(std::size_t n = npos) const;
  double kinetic_energy(std::size_t n = npos) const;  // translation and rotation [J]
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  double max_radius() const;

 private:
  std::uint32_t next_id_ = 0;
  std::size_t wall_stride_ = 0;
};

}  // namespace feedflow
