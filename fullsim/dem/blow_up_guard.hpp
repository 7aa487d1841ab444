#pragma once
// Stops a run that has gone unstable before it produces garbage: an overlap beyond a fraction
// of the radius, a non-finite state, or kinetic energy growing beyond what gravity has fed in
// (KE > growth (KE_0 + W_gravity) + floor, where the floor is M v_design^2 / 2 and, when walls
// move, also M (v_wall + sqrt(2 g dz))^2 / 2: every grain carried at the fastest wall surface
// speed and dropped over the bed's height, a bound a driven bed stays under and a blow-up,
// growing exponentially, leaves within a few steps). Each failure throws NumericalFailure naming the step, the particle
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
  BlowUpGuard(BlowUpLimits limits, double safe_time_step)
      : limits_(limits), safe_dt_(safe_time_step) {}

  // At the start of a run: the kinetic energy and the energy floor [J]; `wall_speed` is the
  // fastest wall surface speed the floor allows for (0: no moving walls) [m/s].
  void start(double kinetic_energy, double floor, double wall_speed = 0.0);
  // Raises the floor to at least `floor` [J] for walls moving up to `wall_speed` [m/s] (a
  // restored run whose walls were set moving after the checkpoint).
  void allow_moving_walls(double floor, double wall_speed) {
    floor_ = floor_ > floor ? floor_ : floor;
    wall_speed_ = wall_speed;
  }
  // Work done by gravity during one step [J].
  void add_gravity_work(double work) { gravity_work_ += work; }
  // Kinetic energy brought in by particles inserted during the run [J] (booked as initial).
  void add_inserted_energy(double energy) { initial_energy_ += energy; }

  void check_overlap(const DeepestOverlap& deepest, const ParticleStore& p, long step) const;
  void check_state(const ParticleStore& p, double kinetic_energy, long step) const;
  // The step `dt` against the stiffest current spring (`period`, described by `spring`):
  // beyond period / pi (omega dt > 2) velocity Verlet cannot hold that contact, so the run
  // stops naming the contact's particle (`slot`) and the stable step for it, `safe_dt`.
  void check_spring(double dt, double period, const std::string& spring, double safe_dt,
                    const ParticleStore& p, std::size_t slot, long step) const;

  // The energy book (checkpoints): initial kinetic energy, floor, gravity work so far [J], and
  // the wall surface speed the floor allows for [m/s] (0: set while every wall stood still).
  double initial_energy() const { return initial_energy_; }
  double energy_floor() const { return floor_; }
  double gravity_work() const { return gravity_work_; }
  double wall_speed() const { return wall_speed_; }
  void resume(double initial_energy, double floor, double gravity_work, double wall_speed) {
    initial_energy_ = initial_energy;
    floor_ = floor;
    gravity_work_ = gravity_work;
    wall_speed_ = wall_speed;
  }

  const BlowUpLimits& limits() const { return limits_; }
  std::string describe() const;

 private:
  [[noreturn]] void fail(const std::string& what, const ParticleStore& p, std::size_t slot,
                         long step, double safe_dt = 0.0) const;
  BlowUpLimits limits_;
  double safe_dt_ = 0.0;
  double wall_speed_ = 0.0;
  double initial_energy_ = 0.0;
  double floor_ = 0.0;
  double gravity_work_ = 0.0;
};

}  // namespace feedflow
