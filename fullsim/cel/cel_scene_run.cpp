#include "fullsim/cel/cel_scene_run.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdio>

#include "fullsim/cel/cel_checkpoint.hpp"
#include "fullsim/cel/cel_field_snapshots.hpp"

namespace feedflow::cel {
namespace {

CelOptions gravity_phase_options(const CelScene& scene) {
  CelOptions o = scene.options;
  o.gravity_ramp_time = scene.gravity.ramp_time;
  o.settling_damping = scene.gravity.settling_damping;
  return o;
}

// The field snapshots of a run (CelSceneRun::snapshot_writer).
class FieldSnapshotWriter final : public SnapshotWriter {
 public:
  FieldSnapshotWriter(const CelSolver& solver, std::filesystem::path file, bool continuing)
      : solver_(solver), snapshots_(std::move(file), continuing) {}
  void write() override {
    if (solver_.step_count() != last_step_) snapshots_.write(solver_);
    last_step_ = solver_.step_count();
  }
  std::size_t count() const override { return snapshots_.count(); }
  std::vector<std::filesystem::path> files() const override {
    return {snapshots_.file(), snapshots_.sidecar()};
  }

 private:
  const CelSolver& solver_;
  CelFieldSnapshots snapshots_;
  long last_step_ = -1;
};

}  // namespace

std::string describe(const RemapOptions& o) {
  std::string state = "first-order";
  if (o.second_order_stress || o.second_order_void_ratio || o.second_order_density ||
      o.second_order_momentum) {
    state = "second-order (van Leer MUSCL:";
    if (o.second_order_stress) state += " stress";
    if (o.second_order_void_ratio) state += " void ratio";
    if (o.second_order_density) state += " density";
    if (o.second_order_momentum) state += " momentum";
    state += ")";
  }
  const char* flux = o.material_flux == MaterialFlux::plic      ? "PLIC (Youngs)"
                     : o.material_flux == MaterialFlux::limited ? "limited MUSCL"
                                                                : "donor-cell";
  return state + " state, " + flux + " material flux";
}

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

void CelSceneRun::prepare(std::ostream& log) {
  if (prepared_) return;
  prepared_ = true;
  updates_at_prepare_ = solver_.cell_updates();
  steps_at_prepare_ = solver_.step_count();
  const CelOptions& o = scene_.options;
  log << "CEL-FEM plan (" << symmetry_name(scene_.grid.symmetry)
      << ", hypoplastic G-B, remap: " << describe(o.remap) << "; mixed cells: "
      << (o.mixed_cells == MixedCellRule::void_first ? "void first" : "equal strain rate")
      << "; walls: " << (o.wall_cells == WallCells::cut ? "cut cells" : "staircase") << ", "
      << omp_get_max_threads() << " OpenMP thread(s)):\n";
  for (const auto& line : scene_.plan) log << "  " << line << '\n';
  const GravityPhase& g = scene_.gravity;
  char text[600];
  std::snprintf(text, sizeof text,
                "  gravity phase: smooth-step ramp over %.3g s, dynamic relaxation %.3g 1/s "
                "(off after the phase), ends after %.3g s when the kinetic energy < %.0e x "
                "its peak, at the latest at %.3g s; bulk viscosity %.3g/%.3g\n"
                "  event: %s; mass scaling: none\n",
                g.ramp_time, g.settling_damping, std::max(g.ramp_time, g.min_time),
                g.kinetic_energy_ratio, g.max_time, o.forces.linear_bulk_viscosity,
                o.forces.quadratic_bulk_viscosity, scene_.event.description.c_str());
  log << text;
}

long CelSceneRun::advance_to(double t, long max_steps) {
  auto scope = report_.time("steps");
  const bool before_event = run_.phase == ScenePhase::gravity;
  long taken = 0;
  while (taken < max_steps && !reached(t)) {
    step();
    ++taken;
    if (before_event && run_.phase == ScenePhase::event) break;
  }
  return taken;
}

std::optional<double> CelSceneRun::event_started_at() const {
  if (run_.phase != ScenePhase::event) return std::nullopt;
  return run_.event_time;
}

void CelSceneRun::write_checkpoint(Hdf5File& file) const { write_cel_checkpoint(file, *this); }

void CelSceneRun::restore(const Hdf5File& file) {
  const CelCheckpoint c = read_cel_checkpoint(file, scene_.grid);
  restore(c.solver, c.run);
}

std::unique_ptr<SnapshotWriter> CelSceneRun::snapshot_writer(const std::filesystem::path& folder,
                                                             bool continuing) const {
  return std::make_unique<FieldSnapshotWriter>(solver_, folder / "fields.h5", continuing);
}

double CelSceneRun::cell_updates_per_second() const {
  const double seconds = report_.phase_seconds("steps");
  return seconds > 0.0 ? static_cast<double>(solver_.cell_updates() - updates_at_prepare_) / seconds
                       : 0.0;
}

RunReport CelSceneRun::performance() const {
  RunReport r = report_;
  char text[160];
  std::snprintf(text, sizeof text, "%.3g cell updates/s (%d thread(s))", cell_updates_per_second(),
                omp_get_max_threads());
  r.add_figure("throughput", text);
  std::snprintf(text, sizeof text, "%ld steps, last dt %.3g s, simulated %.4g s",
                solver_.step_count() - steps_at_prepare_, solver_.last_dt(), solver_.time());
  r.add_figure("steps", text);
  std::snprintf(text, sizeof text, "%zu of %zu cells active at the end",
                solver_.active_cells().size(), solver_.grid().cell_count());
  r.add_figure("cells", text);
  return r;
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
