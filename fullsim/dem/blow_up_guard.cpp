#include "fullsim/dem/blow_up_guard.hpp"

#include <cmath>
#include <cstdio>

#include "models/core/errors.hpp"

namespace feedflow {

void BlowUpGuard::start(double kinetic_energy, double floor, double wall_speed) {
  initial_energy_ = kinetic_energy;
  floor_ = floor;
  wall_speed_ = wall_speed;
  gravity_work_ = 0.0;
}

void BlowUpGuard::fail(const std::string& what, const ParticleStore& p, std::size_t slot,
                       long step, double safe_dt) const {
  char buf[600];
  const Vec3& x = p.position[slot];
  std::snprintf(buf, sizeof buf,
                "DEM blow-up at step %ld: %s; particle id %u at (%.6g, %.6g, %.6g) m. "
                "A safe time step is %.4g s (or below).",
                step, what.c_str(), p.id[slot], x.x(), x.y(), x.z(),
                safe_dt > 0.0 ? safe_dt : safe_dt_);
  throw NumericalFailure(buf);
}

void BlowUpGuard::check_spring(double dt, double period, const std::string& spring,
                               double safe_dt, const ParticleStore& p, std::size_t slot,
                               long step) const {
  constexpr double kPi = 3.14159265358979323846;
  if (!(period > 0.0) || dt * kPi <= period) return;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "time step %.4g s beyond the stability limit %.4g s (period / pi) of the "
                "stiffest current spring, %s",
                dt, period / kPi, spring.c_str());
  fail(buf, p, slot, step, safe_dt);
}

void BlowUpGuard::check_overlap(const DeepestOverlap& deepest, const ParticleStore& p,
                                long step) const {
  if (!(deepest.ratio <= limits_.max_overlap_ratio)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s overlap %.3g R exceeds %.3g R",
                  deepest.with_wall ? "particle-wall" : "particle-particle", deepest.ratio,
                  limits_.max_overlap_ratio);
    fail(buf, p, deepest.slot, step);
  }
}

void BlowUpGuard::check_state(const ParticleStore& p, double kinetic_energy, long step) const {
  if (!std::isfinite(kinetic_energy)) {
    for (std::size_t k = 0; k < p.size(); ++k)
      if (!p.velocity[k].allFinite() || !p.position[k].allFinite() ||
          !p.angular_velocity[k].allFinite())
        fail("non-finite state", p, k, step);
  }
  const double allowed =
      limits_.energy_growth * (initial_energy_ + std::max(gravity_work_, 0.0)) + floor_;
  if (kinetic_energy > allowed && p.size() > 0) {
    std::size_t fastest = 0;
    for (std::size_t k = 1; k < p.size(); ++k)
      if (p.velocity[k].squaredNorm() > p.velocity[fastest].squaredNorm()) fastest = k;
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "kinetic energy %.4g J grew beyond %.4g J (%.3g x (initial + gravity work))",
                  kinetic_energy, allowed, limits_.energy_growth);
    fail(buf, p, fastest, step);
  }
}

std::string BlowUpGuard::describe() const {
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "blow-up guard: overlap > %.3g R; kinetic energy > %.3g x (initial + gravity "
                "work) + %.4g J",
                limits_.max_overlap_ratio, limits_.energy_growth, floor_);
  std::string text = buf;
  if (wall_speed_ > 0.0) {
    std::snprintf(buf, sizeof buf, " (allows for moving walls up to %.3g m/s)", wall_speed_);
    text += buf;
  }
  return text;
}

}  // namespace feedflow
