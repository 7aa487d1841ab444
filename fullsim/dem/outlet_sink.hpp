#pragma once
// An outlet sink: particles whose centre enters its region (an axis-aligned box, or the far
// side of a plane) are removed; their mass and the time are booked.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fullsim/dem/particle_store.hpp"

namespace feedflow {

struct SinkEvent {
  double time = 0.0;         // [s]
  std::uint32_t id = 0;
  double mass = 0.0;         // [kg]
  double layer = 0.0;        // the particle's layer (ParticleStore::layer), e.g. its fill band
};

class OutletSink {
 public:
  // Removes what lies inside [lower, upper].
  static OutletSink box(const Vec3& lower, const Vec3& upper);
  // Removes what lies beyond the plane through `point` (on the side `outward` points to).
  static OutletSink plane(const Vec3& point, const Vec3& outward);

  // A sink as saved in a checkpoint, with its booked mass and events, taken as is.
  static OutletSink restored(bool is_box, const Vec3& a, const Vec3& b, double removed_mass,
                             std::vector<SinkEvent> events);
  bool is_box() const { return is_box_; }
  const Vec3& lower_or_point() const { return a_; }
  const Vec3& upper_or_outward() const { return b_; }

  bool captures(const Vec3& x) const;
  // Removes the captured particles of the store at time t; returns how many.
  std::size_t remove(ParticleStore& particles, double t);

  double removed_mass() const { return removed_mass_; }   // [kg]
  std::size_t removed_count() const { return events_.size(); }
  const std::vector<SinkEvent>& events() const { return events_; }
  std::string describe() const;

 private:
  bool is_box_ = true;
  Vec3 a_ = Vec3::Zero();  // box lower or plane point
  Vec3 b_ = Vec3::Zero();  // box upper or outward normal
  double removed_mass_ = 0.0;
  std::vector<SinkEvent> events_;
};

}  // namespace feedflow
