#pragma once
// Stable DEM time step (models.md 5.1): the smallest of
// - the stiffest current spring: (2 pi sqrt(m/k)) / N, over the normal spring (largest of the
//   hysteretic loading and unloading slopes, or the Hertz/Hooke slope) with m = m*, the
//   tangential spring with the contact point's effective mass (2/7) m* of two spheres, and the
//   rolling spring k_r with I_eff;
// - a fraction of the Rayleigh time T_R = pi R sqrt(rho/G) / (0.1631 nu + 0.8766);
// - a fraction of the Hertz collision time as LIGGGHTS `check/timestep/gran` computes it,
//   t_H = 2.87 (m^2 / (R* E*^2 v_rel))^(1/5), m one particle's mass, R* = R/2, v_rel = 2 v_max;
// with a one-line justification naming the criterion that limits it.
#include <string>
#include <string_view>

#include "models/contact/contact_kinematics.hpp"
#include "models/contact/contact_law_registry.hpp"
#include "models/material/dem_parameters.hpp"

namespace feedflow {

struct TimeStepSettings {
  double steps_per_period = 20.0;  // N: steps per period of the stiffest spring
  double rayleigh_fraction = 0.2;  // dt <= this * T_R (the INL decks' check)
  double hertz_fraction = 0.2;     // dt <= this * t_H
  double max_velocity = 1.0;       // v_max for t_H [m/s]
  double design_overlap = 0.1;     // overlap / radius at which springs are taken before a run
};

struct StableTimeStep {
  double value = 0.0;         // [s]
  std::string justification;  // one line, names the limiting criterion
};

double rayleigh_time(double radius, double density, double youngs_modulus, double poisson_ratio);
double hertz_collision_time(double particle_mass, double effective_radius,
                            double effective_youngs_modulus, double relative_velocity);

// The spring with the shortest period among those added.
class StiffestSpring {
 public:
  // One contact's springs; `where` names the contact kind ("P-P", "P-W").
  void add(const ContactStiffness& k, double effective_mass, double effective_inertia,
           double overlap, std::string_view where);
  bool empty() const { return period_ == 0.0; }
  double period() const { return period_; }      // [s]
  const std::string& description() const { return description_; }

 private:
  void consider(double period, const std::string& what);
  double period_ = 0.0;
  std::string description_;
};

// Before a run: the springs of the P-P and P-W laws for a contact loaded to the design overlap
// and reversed once (so the hysteretic k1 = A1 delta_max + A2 applies), between two particles
// (R* = R/2, m* = m/2) and between a particle and a wall (R* = R, m* = m).
StiffestSpring design_springs(const DemParameters& dem, const ContactLawChoice& particle_particle,
                              const ContactLawChoice& particle_wall, double design_overlap);

// During a run: the springs of the deepest current P-P and P-W contacts, each at its own
// overlap over the radius (0: no such contact, not added), loaded and reversed once like the
// design springs. Every law's springs stiffen with the overlap (Hertz sqrt(delta), the
// hysteretic unloading slope k1 = A1 delta_max + A2), so these are the stiffest of the run now.
StiffestSpring current_springs(const DemParameters& dem, const ContactLawChoice& law,
                               double particle_particle_ratio, double particle_wall_ratio);

StableTimeStep stable_time_step(const DemParameters& dem, const StiffestSpring& springs,
                                const TimeStepSettings& settings);

}  // namespace feedflow
