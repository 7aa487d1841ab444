#pragma once
// A CEL scene run: the solver with the scene's material, the gravity phase (gravity ramped,
// dynamic relaxation on) ended once the ramp is over, the minimum time has passed and the
// kinetic energy has fallen below a fraction of its peak (or at the maximum time), then the
// event (walls removed or set moving, damping off) and the flow after it. It implements the
// stepper contract of the scene run loop (fullsim/common/stepper.hpp) on the solver's adaptive
// step; its scene event is the end of the gravity phase.
#include <limits>

#include "fullsim/cel/cel_scene.hpp"
#include "fullsim/common/run_report.hpp"
#include "fullsim/common/stepper.hpp"

namespace feedflow::cel {

enum class ScenePhase { gravity, event };

// The run's own state beside the solver's (for checkpoints).
struct SceneRunState {
  ScenePhase phase = ScenePhase::gravity;
  double event_time = std::numeric_limits<double>::quiet_NaN();  // [s]
  double peak_kinetic_energy = 0.0;                               // of the gravity phase [J/m]
};

class CelSceneRun final : public Stepper {
 public:
  CelSceneRun(const CelScene& scene, const HypoplasticModel& model);

  // One solver step; ends the gravity phase and starts the event when its criterion holds.
  CelStepReport step();

  // The stepper contract: the plan is the scene's (remap, mixed cells, threads, walls, the
  // gravity phase and the event); time steps are the solver's own (never shortened).
  void prepare(std::ostream& log) override;
  long advance_to(double t, long max_steps = kUnbounded) override;
  bool reached(double t) const override { return solver_.time() >= t; }
  double whole_steps(double duration, StepRounding) const override { return duration; }
  double time() const override { return solver_.time(); }
  long steps() const override { return solver_.step_count(); }
  std::optional<double> event_started_at() const override;
  double event_time() const { return run_.event_time; }  // NaN during the gravity phase
  // Format "feedflow CEL checkpoint" (cel_checkpoint.hpp).
  void write_checkpoint(Hdf5File& file) const override;
  void restore(const Hdf5File& file) override;
  // fields.h5 with its XDMF sidecar (cel_field_snapshots.hpp), continued by a restarted run.
  std::unique_ptr<SnapshotWriter> snapshot_writer(const std::filesystem::path& folder,
                                                  bool continuing) const override;
  // Time in the steps, cell updates per second, steps and active cells since prepare().
  RunReport performance() const override;
  double cell_updates_per_second() const;

  const CelScene& scene() const { return scene_; }
  CelSolver& solver() { return solver_; }
  const CelSolver& solver() const { return solver_; }
  ScenePhase phase() const { return run_.phase; }
  double initial_mass() const { return initial_mass_; }  // [kg/m]
  const SceneRunState& run_state() const { return run_; }
  void restore(const CelSolverState& solver_state, const SceneRunState& run_state);

 private:
  void start_event();

  CelScene scene_;
  CelSolver solver_;
  SceneRunState run_;
  double initial_mass_ = 0.0;
  RunReport report_{"CEL-FEM run"};
  long updates_at_prepare_ = 0, steps_at_prepare_ = 0;
  bool prepared_ = false;
};

// "first-order state, donor-cell material flux" (the plan's words for the remap).
std::string describe(const RemapOptions& remap);

}  // namespace feedflow::cel
