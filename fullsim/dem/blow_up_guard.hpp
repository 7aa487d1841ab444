#pragma once
// Stops a run that has gone unstable before it produces garbage: an overlap beyond a fraction
// of the radius, a non-finite state, or kinetic energy growing beyond what gravity has fed in
// (KE > growth (KE_0 + W_gravity) + M v_design^2 / 2; not checked when walls move, as they feed energy
// the guard does not book). Each failure throws NumericalFailure naming the step, the particle
// id, its position and a safe time step.
#include <string>

#include "fullsim/dem/force_kernel.hpp"
#include "fullsim/dem/particle_store.hpp"

namespace feedflow {

struct BlowUpLimits {
  double max_overlap_ratio = 0.3;  // overlap / radius
  double energy_growth = 2.0;      // allowed factor on KE_0 + gravity work
};

class BlowUpGuard {
 public:
  BlowUpGuard() = default;
  BlowUpGuard(BlowUpLimits limits, double safe_time_step, bool check_energy)
      : limits_(limits), safe_dt_(safe_time_step), check_energy_(check_energy) {}

  // At the start of a run: the kinetic energy and the energy floor [J].
  void start(double kinetic_energy, double floor);
  // Work done by gravity during one step [J].
  void add_gravity_work(double work) { gravity_work_ += work; }
  // Kinetic energy brought in by particles inserted during the run [J] (booked as initial).
  void add_inserted_energy(double energy) { initial_energy_ += energy; }

  void check_overlap(const DeepestOverlap& deepest, const ParticleStore& p, long step) const;
  void check_state(const ParticleStore& p, double kinetic_energy, long step) const;

  // The energy book (checkpoints): initial kinetic energy, floor, gravity work so far [J].
  double initial_energy() const { return initial_energy_; }
  double energy_floor() const { return floor_; }
  double gravity_work() const { return gravity_work_; }
  void resume(double initial_energy, double floor, double gravity_work) {
    initial_energy_ = initial_energy;
    floor_ = floor;
    gravity_work_ = gravity_work;
  }

  bool checks_energy() const { return check_energy_; }
  const BlowUpLimits& limits() const { return limits_; }
  std::string describe() const;

 private:
  [[noreturn]] void fail(const std::string& what, const ParticleStore& p, std::size_t slot,
                         long step) const;
  BlowUpLimits limits_;
  double safe_dt_ = 0.0;
  bool check_energy_ = true;
  double initial_energy_ = 0.0;
  double floor_ = 0.0;
  double gravity_work_ = 0.0;
};

}  // namespace feedflow
