#include "fullsim/dem/outlet_sink.hpp"

#include <algorithm>
#include <cstdio>

namespace feedflow {

OutletSink OutletSink::box(const Vec3& lower, const Vec3& upper) {
  OutletSink s;
  s.is_box_ = true;
  s.a_ = lower;
  s.b_ = upper;
  return s;
}

OutletSink OutletSink::plane(const Vec3& point, const Vec3& outward) {
  OutletSink s;
  s.is_box_ = false;
  s.a_ = point;
  s.b_ = outward.normalized();
  return s;
}

OutletSink OutletSink::restored(bool is_box, const Vec3& a, const Vec3& b, double removed_mass,
                                std::vector<SinkEvent> events) {
  OutletSink s;
  s.is_box_ = is_box;
  s.a_ = a;
  s.b_ = b;
  s.removed_mass_ = removed_mass;
  s.events_ = std::move(events);
  return s;
}

bool OutletSink::captures(const Vec3& x) const {
  if (!is_box_) return (x - a_).dot(b_) > 0.0;
  return (x.array() >= a_.array()).all() && (x.array() <= b_.array()).all();
}

std::size_t OutletSink::remove(ParticleStore& particles, double t) {
  std::vector<char> flagged(particles.size(), 0);
  std::size_t count = 0;
  const std::size_t first_new = events_.size();
  for (std::size_t k = 0; k < particles.size(); ++k) {
    if (!captures(particles.position[k])) continue;
    flagged[k] = 1;
    ++count;
    removed_mass_ += particles.mass[k];
    events_.push_back({t, particles.id[k], particles.mass[k], particles.layer[k]});
  }
  // Booked in id order within one removal, so the books do not depend on the store's order
  // (which the neighbour sort and the ranks change).
  std::sort(events_.begin() + static_cast<std::ptrdiff_t>(first_new), events_.end(),
            [](const SinkEvent& a, const SinkEvent& b) { return a.id < b.id; });
  if (count > 0) particles.remove_flagged(flagged);
  return count;
}

std::string OutletSink::describe() const {
  char buf[200];
  if (is_box_)
    std::snprintf(buf, sizeof buf, "outlet sink: box (%.4g, %.4g, %.4g)-(%.4g, %.4g, %.4g)", a_.x(),
                  a_.y(), a_.z(), b_.x(), b_.y(), b_.z());
  else
    std::snprintf(buf, sizeof buf, "outlet sink: beyond plane through (%.4g, %.4g, %.4g) towards (%.3g, %.3g, %.3g)",
                  a_.x(), a_.y(), a_.z(), b_.x(), b_.y(), b_.z());
  return buf;
}

}  // namespace feedflow
