#pragma once
// A CEL scene run: the solver with the scene's material, the gravity phase (gravity ramped,
// dynamic relaxation on) ended once the ramp is over, the minimum time has passed and the
// kinetic energy has fallen below a fraction of its peak (or at the maximum time), then the
// event (walls removed or set moving, damping off) and the flow after it.
#include <limits>

#include "fullsim/cel/cel_scene.hpp"

namespace feedflow::cel {

enum class ScenePhase { gravity, event };

// The run's own state beside the solver's (for checkpoints).
struct SceneRunState {
  ScenePhase phase = ScenePhase::gravity;
  double event_time = std::numeric_limits<double>::quiet_NaN();  // [s]
  double peak_kinetic_energy = 0.0;                               // of the gravity phase [J/m]
};

class CelSceneRun {
 public:
  CelSceneRun(const CelScene& scene, const HypoplasticModel& model);

  // One solver step; ends the gravity phase and starts the event when its criterion holds.
  CelStepReport step();

  const CelScene& scene() const { return scene_; }
  CelSolver& solver() { return solver_; }
  const CelSolver& solver() const { return solver_; }
  ScenePhase phase() const { return run_.phase; }
  double event_time() const { return run_.event_time; }  // NaN during the gravity phase
  double initial_mass() const { return initial_mass_; }  // [kg/m]
  const SceneRunState& run_state() const { return run_; }
  void restore(const CelSolverState& solver_state, const SceneRunState& run_state);

 private:
  void start_event();

  CelScene scene_;
  CelSolver solver_;
  SceneRunState run_;
  double initial_mass_ = 0.0;
};

}  // namespace feedflow::cel
