#include "fullsim/cel/cel_scene_run.hpp"

#include <algorithm>

namespace feedflow::cel {
namespace {

CelOptions gravity_phase_options(const CelScene& scene) {
  CelOptions o = scene.options;
  o.gravity_ramp_time = scene.gravity.ramp_time;
  o.settling_damping = scene.gravity.settling_damping;
  return o;
}

}  // namespace

CelSceneRun::CelSceneRun(const CelScene& scene, const HypoplasticModel& model)
    : scene_(scene), solver_(scene.grid, model, gravity_phase_options(scene)) {
  for (const auto& block : scene_.material) solver_.add_material(block);
  initial_mass_ = solver_.total_mass();
}

CelStepReport CelSceneRun::step() {
  CelStepReport report = solver_.step();
  if (run_.phase == ScenePhase::gravity) {
    const double ke = solver_.kinetic_energy(), t = solver_.time();
    run_.peak_kinetic_energy = std::max(run_.peak_kinetic_energy, ke);
    const GravityPhase& g = scene_.gravity;
    const bool rested = t >= std::max(g.ramp_time, g.min_time) &&
                        ke <= g.kinetic_energy_ratio * run_.peak_kinetic_energy;
    if (rested || t >= g.max_time) start_event();
  }
  return report;
}

void CelSceneRun::start_event() {
  const double t = solver_.time();
  run_.phase = ScenePhase::event;
  run_.event_time = t;
  solver_.set_settling_damping(0.0);
  if (scene_.event.frame_started) solver_.start_turning_frame();
  for (std::size_t k : scene_.event.walls_removed) solver_.rigid_wall(k).removal_time = t;
  for (std::size_t k : scene_.event.walls_started) {
    solver_.rigid_wall(k).motion_start = t;
    solver_.rigid_wall(k).motion_end = t + scene_.event.motion_duration;
  }
}

void CelSceneRun::restore(const CelSolverState& solver_state, const SceneRunState& run_state) {
  solver_.restore(solver_state);
  run_ = run_state;
}

}  // namespace feedflow::cel
