#pragma once
// Rung L1 chute model: integrates the ramp-flow scheme (ramp_flow_scheme.hpp) in time with
// SUNDIALS ARKODE (ERKStep, Heun's SSP Runge-Kutta 2 with its Euler embedding, fixed CFL steps)
// by the method of lines, applies the implicit Coulomb stopping step after every stage (ERKStep's
// stage post-processing) and the step's friction after every step, records
// the front and the velocities, and stops once the kinetic energy has fallen below a fraction of
// its peak (or the flow is exactly at rest).
#include <cstddef>
#include <vector>

#include "models/chute/ramp_flow_scheme.hpp"

namespace feedflow {

struct RampFlowSettings {
  double cfl = 0.4;                     // a dt/dx (positivity needs <= 0.5)
  double max_step = 1e-2;               // [s], for a dry or resting domain
  double end_time = 120.0;              // give up (stopped = false) after this [s]
  double min_time = 0.0;                // never stop before this (for tests at rest) [s]
  double stop_kinetic_fraction = 1e-6;  // stop when KE <= this fraction of its peak
  double sample_interval = 0.05;        // time between recorded samples [s]
  double ramp_begin = 0.0;              // x where the ramp (outside any bin) starts [m]
  double probe_position = 0.0;          // where the stopping thickness is read [m]
  double front_threshold = 1e-4;        // thinnest layer that counts as material [m]
};

struct RampFlowSample {
  double time;            // [s]
  double front_position;  // x of the farthest cell thicker than front_threshold [m]
  double front_velocity;  // depth-averaged velocity there [m/s]
  double mean_velocity;   // volume-weighted depth-averaged velocity on the ramp [m/s]
  double probe_velocity;  // depth-averaged velocity at the probe [m/s]
  double kinetic_energy;  // sum h u^2/2 dx over the domain [m^4/s^2 = J/(kg/m^3 * m width)]
};

struct RampFlowResult {
  std::vector<double> x;          // cell centres [m]
  std::vector<double> thickness;  // h at the end (the deposit once stopped) [m]
  std::vector<double> velocity;   // u at the end [m/s]
  std::vector<RampFlowSample> samples;
  bool stopped = false;           // the stop criterion was met before end_time
  double stop_time = 0.0;         // [s]
  double probe_thickness = 0.0;   // h at probe_position, linear between centres [m]
  double initial_volume = 0.0;    // per unit width [m^2]
  double final_volume = 0.0;      // on the domain at the end [m^2]
  double outflow_volume = 0.0;    // left through outflow ends [m^2]
  std::size_t steps = 0;
  long rhs_evaluations = 0;
};

// Runs from the given state (h, and q = h u; q empty means at rest). Throws
// std::invalid_argument for inconsistent input and NumericalFailure (with time, place and a
// remedy) when ARKODE fails or a thickness turns negative.
RampFlowResult run_ramp_flow(const RampGrid& grid, const RampPhysics& physics,
                             const std::vector<double>& thickness,
                             const std::vector<double>& discharge,
                             const RampFlowSettings& settings);

}  // namespace feedflow
