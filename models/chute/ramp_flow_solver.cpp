#include "models/chute/ramp_flow_solver.hpp"

#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "models/core/errors.hpp"

namespace feedflow {
namespace {

// Owns the SUNDIALS objects of one run.
struct Integrator {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  void* arkode = nullptr;
  ~Integrator() {
    if (arkode) ERKStepFree(&arkode);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
  }
};

struct RhsData {
  RampFlowScheme* scheme;
  long evaluations = 0;
  double step_start = 0.0;  // t_n of the step under way
};

int rhs_callback(realtype, N_Vector y, N_Vector ydot, void* user) {
  auto* data = static_cast<RhsData*>(user);
  ++data->evaluations;
  return data->scheme->rhs(N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) ? 0 : -1;
}

// Friction on every Runge-Kutta stage: the stage z_i = y_n + dt sum a_ij f_j spans c_i dt, so
// its Coulomb stopping step (backward Euler) spans the same time. With Heun (c_2 = 1) that is a
// first-order predictor, enough for the corrector, whose friction end_step applies
// trapezoidally; a cell held by friction stays at q == 0 on every stage.
int stage_friction_callback(realtype t, N_Vector y, void* user) {
  auto* data = static_cast<RhsData*>(user);
  const double span = t - data->step_start;
  if (span > 0.0) data->scheme->apply_friction(N_VGetArrayPointer(y), span);
  return 0;
}

std::string at(double t, double x) {
  return " at t = " + std::to_string(t) + " s, x = " + std::to_string(x) + " m";
}

double kinetic_energy(const RampFlowScheme& s, const double* y) {
  const std::size_t n = s.grid().cells;
  double e = 0.0;
  for (std::size_t i = 0; i < n; ++i) e += 0.5 * y[n + i] * s.velocity(y[i], y[n + i]);
  return e * s.grid().dx();
}

double volume(const RampFlowScheme& s, const double* y) {
  double v = 0.0;
  for (std::size_t i = 0; i < s.grid().cells; ++i) v += y[i];
  return v * s.grid().dx();
}

RampFlowSample sample(const RampFlowScheme& s, const double* y, double t,
                      const RampFlowSettings& settings) {
  const auto& g = s.grid();
  const std::size_t n = g.cells;
  RampFlowSample out{t, settings.ramp_begin, 0.0, 0.0, 0.0, kinetic_energy(s, y)};
  double hv = 0.0, qv = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (g.centre(i) < settings.ramp_begin) continue;
    hv += y[i];
    qv += y[n + i];
    if (y[i] > settings.front_threshold) {
      out.front_position = g.centre(i);
      out.front_velocity = s.velocity(y[i], y[n + i]);
    }
  }
  out.mean_velocity = hv > 0.0 ? qv / hv : 0.0;
  const auto probe = static_cast<std::size_t>(
      std::clamp((settings.probe_position - g.x_begin) / g.dx(), 0.0, double(n - 1)));
  out.probe_velocity = s.velocity(y[probe], y[n + probe]);
  return out;
}

double interpolate(const RampGrid& g, const std::vector<double>& h, double x) {
  const double p = std::clamp((x - g.x_begin) / g.dx() - 0.5, 0.0, double(g.cells - 1));
  const auto i = std::min(static_cast<std::size_t>(p), g.cells - 2);
  const double w = p - double(i);
  return (1.0 - w) * h[i] + w * h[i + 1];
}

}  // namespace

RampFlowResult run_ramp_flow(const RampGrid& grid, const RampPhysics& physics,
                             const std::vector<double>& thickness,
                             const std::vector<double>& discharge,
                             const RampFlowSettings& settings) {
  RampFlowScheme scheme(grid, physics);
  const std::size_t n = grid.cells;
  if (thickness.size() != n || (!discharge.empty() && discharge.size() != n))
    throw std::invalid_argument("ramp flow: initial state must have one value per cell");
  if (!std::all_of(thickness.begin(), thickness.end(), [](double h) { return h >= 0.0; }))
    throw std::invalid_argument("ramp flow: initial thickness must be >= 0");
  if (!(settings.cfl > 0.0 && settings.cfl <= 0.5) || !(settings.end_time > 0.0) ||
      !(settings.sample_interval > 0.0) || !(settings.max_step > 0.0))
    throw std::invalid_argument("ramp flow: need 0 < cfl <= 0.5 and positive times");

  Integrator in;
  if (SUNContext_Create(nullptr, &in.context) != 0)
    throw NumericalFailure("ramp flow: SUNContext_Create failed");
  in.y = N_VNew_Serial(static_cast<sunindextype>(scheme.state_size()), in.context);
  double* y = N_VGetArrayPointer(in.y);
  std::copy(thickness.begin(), thickness.end(), y);
  for (std::size_t i = 0; i < n; ++i) y[n + i] = discharge.empty() ? 0.0 : discharge[i];
  y[2 * n] = 0.0;

  RhsData data{&scheme};
  in.arkode = ERKStepCreate(rhs_callback, 0.0, in.y, in.context);
  if (!in.arkode || ERKStepSetUserData(in.arkode, &data) != ARK_SUCCESS ||
      ERKStepSetTableNum(in.arkode, ARKODE_HEUN_EULER_2_1_2) != ARK_SUCCESS ||
      ERKStepSetPostprocessStageFn(in.arkode, stage_friction_callback) != ARK_SUCCESS)
    throw NumericalFailure("ramp flow: ARKODE ERKStep set-up failed");

  RampFlowResult result;
  result.initial_volume = volume(scheme, y);
  double t = 0.0, next_sample = 0.0, peak_energy = 0.0;
  int quiet_steps = 0;
  const double h_scale = *std::max_element(thickness.begin(), thickness.end());
  while (true) {
    const double energy = kinetic_energy(scheme, y);
    if (t >= next_sample) {
      result.samples.push_back(sample(scheme, y, t, settings));
      next_sample += settings.sample_interval;
    }
    peak_energy = std::max(peak_energy, energy);
    const bool all_rest = std::all_of(y + n, y + 2 * n, [](double q) { return q == 0.0; });
    quiet_steps = all_rest ? quiet_steps + 1 : 0;
    if (t >= settings.min_time && ((peak_energy > 0.0 && energy <= settings.stop_kinetic_fraction * peak_energy) ||
        quiet_steps >= 2)) {
      result.stopped = true;
      break;
    }
    if (t >= settings.end_time) break;

    const double speed = scheme.max_wave_speed(y);
    const double dt = std::min({settings.max_step, speed > 0.0 ? settings.cfl * grid.dx() / speed
                                                               : settings.max_step,
                                settings.end_time - t + 1e-12});
    scheme.begin_step(y);
    data.step_start = t;
    realtype t_reached = t;
    int flag = ERKStepSetFixedStep(in.arkode, dt);
    if (flag == ARK_SUCCESS) flag = ERKStepEvolve(in.arkode, t + dt, in.y, &t_reached, ARK_ONE_STEP);
    y = N_VGetArrayPointer(in.y);
    if (flag < 0)
      throw NumericalFailure("ramp flow: ARKODE ERKStep failed (flag " + std::to_string(flag) +
                             ")" + at(t, grid.centre(scheme.failed_cell())) +
                             "; a smaller cfl or a coarser grid on a thin layer may help");
    for (std::size_t i = 0; i < n; ++i)
      if (y[i] < -1e-12 * h_scale)
        throw NumericalFailure("ramp flow: negative thickness " + std::to_string(y[i]) + " m" +
                               at(t_reached, grid.centre(i)) + "; lower the cfl number");
    scheme.end_step(y, t_reached - t);
    t = t_reached;
    if (ERKStepReset(in.arkode, t, in.y) != ARK_SUCCESS)
      throw NumericalFailure("ramp flow: ERKStepReset failed" + at(t, grid.x_begin));
    ++result.steps;
  }
  result.stop_time = t;
  result.samples.push_back(sample(scheme, y, t, settings));
  result.rhs_evaluations = data.evaluations;
  for (std::size_t i = 0; i < n; ++i) {
    result.x.push_back(grid.centre(i));
    result.thickness.push_back(y[i]);
    result.velocity.push_back(scheme.velocity(y[i], y[n + i]));
  }
  result.final_volume = volume(scheme, y);
  result.outflow_volume = y[2 * n];
  result.probe_thickness = interpolate(grid, result.thickness, settings.probe_position);
  return result;
}

}  // namespace feedflow
