#pragma once
// The DEM time loop (rung L3): velocity Verlet for translation and rotation with gravity
// (LIGGGHTS nve/sphere order, models.md 4.5), neighbour lists rebuilt on a skin criterion and
// re-sorted along a Morton curve, the composed contact law for particle-particle and
// particle-wall contacts (each with its Table 2 parameter set), moving and removable walls,
// periodic axes, an outlet sink, the blow-up guard, the plan written before a run and the
// performance block after it. It implements the stepper contract of the scene run loop
// (fullsim/common/stepper.hpp) with a fixed time step; it writes only to the log it is given.
//
//   DemEngine engine(settings, box, particles);
//   engine.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}));
//   engine.prepare(log);             // plan, time step and its justification
//   engine.run_steps(10000);         // or advance_to(t)
//   log << engine.performance_report();
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fullsim/common/run_report.hpp"
#include "fullsim/common/scene_outline.hpp"
#include "fullsim/common/stepper.hpp"
#include "fullsim/dem/bed_view.hpp"
#include "fullsim/dem/blow_up_guard.hpp"
#include "fullsim/dem/dem_checkpoint.hpp"
#include "fullsim/dem/force_kernel.hpp"
#include "fullsim/dem/mesh_wall.hpp"
#include "fullsim/dem/neighbour_list.hpp"
#include "fullsim/dem/outlet_sink.hpp"
#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/ranks/dem_ranks.hpp"
#include "fullsim/dem/ranks/halo_exchange.hpp"
#include "fullsim/dem/ranks/rank_domains.hpp"
#include "fullsim/dem/simulation_box.hpp"
#include "fullsim/dem/time_step_choice.hpp"
#include "fullsim/dem/wall.hpp"
#include "fullsim/dem/wall_reach.hpp"
#include "models/contact/contact_law_registry.hpp"
#include "models/contact/contact_time_step.hpp"
#include "models/material/dem_parameters.hpp"

namespace feedflow {

struct DemSettings {
  DemParameters material;                    // Table 2: particle, P-P and P-W columns
  ContactLawChoice law;                      // one composition for P-P and P-W contacts
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);      // [m/s^2]
  double skin_fraction = 0.3;                // Verlet skin / largest radius [-]
  std::size_t sort_every = 20;               // re-sort along the Morton curve every N rebuilds
  TimeStepSettings time_step;                // safety factors of the stable step
  double requested_time_step = 0.0;          // [s]; 0: stable_step_fraction x the stable step
  double stable_step_fraction = 1.0;         // of the stable step when no step is requested
  bool force_time_step = false;              // accept a step above the stable one
  BlowUpLimits guard;
  std::size_t parallel_from = 4000;          // fewer particles run on one thread (the
                                             // thread start-up would cost more than it saves)
  // The ranks the run is shared among (ranks/): each owns the particles of its sub-box and
  // holds ghost copies of its neighbours' near ones. Every rank constructs the engine with the
  // same particles and walls; prepare() keeps each rank's own. One rank: no MPI at all.
  DemRanks ranks = DemRanks::one();
  // The sub-boxes are cut again at a rebuild when the most particles a rank owns pass this
  // factor on the mean (a draining hopper, a turning drum).
  double rebalance_above = 1.10;
};

class DemEngine final : public Stepper {
 public:
  DemEngine(DemSettings settings, SimulationBox box, ParticleStore particles);
  // Restores a run from a checkpoint (read_dem_checkpoint(), or one taken by checkpoint()):
  // particles, walls, sink, box, neighbour list with its contact history, step and time.
  // prepare() then checks that `settings` give the checkpoint's contact law, time step and
  // gravity (and throws std::runtime_error naming what differs) instead of rebuilding, so the
  // run continues bit-identically.
  DemEngine(DemSettings settings, DemCheckpoint checkpoint);
  ~DemEngine() override;
  DemEngine(DemEngine&&) noexcept;
  DemEngine& operator=(DemEngine&&) noexcept;

  void add_wall(Wall wall);
  // A triangle-mesh wall (e.g. MeshWall("hopper", read_stl("hopper.stl", 1e-3))).
  void add_mesh_wall(MeshWall mesh);
  void set_outlet_sink(OutletSink sink);
  // Holds every particle in the plane through its centre normal to `axis` (0: x, 1: y, 2: z):
  // no force or velocity along the axis, torque and spin about it only. A one-layer slab whose
  // centres must stay in its mid-plane: without the hold, any round-off across the slab grows
  // (a compressed layer buckles) until the grains press on the faces. The kicks take the
  // forces and torques component by component times 1 or 0, so a run without the hold keeps
  // its bits. Set with the walls (a restored run's engine is built the same way); the
  // velocities of the particles already in the store are projected at once.
  void hold_in_plane(int axis);
  bool holds_in_plane() const { return linear_free_ != Vec3::Ones(); }

  // Filling and trimming between steps (rain-fall insertion, fullsim/dem/scene/): a particle
  // added to a prepared run has its kinetic energy booked with the blow-up guard; after either
  // call the neighbour list is rebuilt at the next step. Before prepare() they only edit the
  // store. On a run shared among ranks every rank inserts the same particles (the owner of the
  // position keeps each) and flags the slots of its own store (a ghost's flag is ignored).
  std::uint32_t insert_particle(const Vec3& x, double radius, double density, double layer,
                                const Vec3& velocity);
  // Removes the particles whose flag (one per slot) is set.
  void remove_particles(const std::vector<char>& flagged);
  // Gravity from the next step's forces on (a layer filled under gravity normal to its ramp,
  // then tilted); the blow-up guard books the work of the gravity of each step. A run restored
  // from a checkpoint must be set to the checkpoint's gravity first (restore refuses another).
  void set_gravity(const Vec3& g) { settings_.gravity = g; }
  const Vec3& gravity() const { return settings_.gravity; }
  // The analytic wall `name` is gone from time `t` on (a gate opened once the fill has
  // settled); throws std::invalid_argument for an unknown name.
  void set_wall_removal_time(const std::string& name, double t);

  // Chooses the kernels and the time step, builds the neighbour list and the first forces,
  // and writes the plan to `out`. The first run_steps() prepares silently if not done before.
  void prepare(std::ostream& out) override;
  // Advances `steps` steps of velocity Verlet (throws NumericalFailure on a blow-up).
  void run_steps(long steps);
  // The stepper contract (fullsim/common/stepper.hpp), on the fixed time step.
  long advance_to(double t, long max_steps = kUnbounded) override;
  bool reached(double t) const override { return steps_to(t) == 0; }
  double whole_steps(double duration, StepRounding rounding) const override;
  long steps() const override { return step_; }

  // The state as it stands (after prepare()), for write_dem_checkpoint().
  DemCheckpoint checkpoint() const;
  // Writes checkpoint() to `path` (whole or nothing), or into an open file.
  void write_checkpoint(const std::filesystem::path& path) const;
  void write_checkpoint(Hdf5File& file) const override;
  bool checkpoint_ready() const override { return prepared_ && !rebuild_due_; }
  bool raised_on_any(bool flag) const override {
    return shared() ? settings_.ranks.max(flag ? 1.0 : 0.0) > 0.0 : flag;
  }
  std::optional<std::string> agreed_failure(std::optional<std::string> mine) const override {
    return settings_.ranks.agree_on_failure(mine);
  }
  bool writes_files() const override { return settings_.ranks.rank() == 0; }
  // The state of the checkpoint in `file`, in place of this engine's particles, analytic walls,
  // sink, neighbour list, step and time (the mesh walls added so far stay); prepare() then
  // checks the settings against it, as for the constructor from a checkpoint.
  void restore(const Hdf5File& file) override;
  // The phase times of an engine this one replaces (a scene that rebuilds its engine, as the
  // drum does to start turning), so that this one's block covers both.
  void add_earlier_phases(const RunReport& earlier);
  // Particle snapshots (particle_snapshots.hpp): particles.h5, or for a continued run
  // particles_from_step_<step>.h5 beside the first part's file.
  std::unique_ptr<SnapshotWriter> snapshot_writer(const std::filesystem::path& folder,
                                                  bool continuing) const override;
  RunReport performance() const override;

  std::string plan() const { return plan_; }
  // On a shared run, each phase's time over the ranks (min / mean / max) and the particles per
  // rank: the lines of the performance block that show the balance (collective; empty alone).
  std::string rank_balance() const;
  std::string performance_report() const;

  double time() const override { return time_; }
  long step() const { return step_; }
  double time_step() const { return time_step_.value; }
  const TimeStepChoice& time_step_choice() const { return time_step_; }
  const ContactLawChoice& effective_law() const { return effective_law_; }
  ParticleStore& particles() { return particles_; }
  const ParticleStore& particles() const { return particles_; }
  // On a run shared among ranks: this rank's own particles are the store's first
  // owned_count() slots, the ghost copies of other ranks' particles follow; alone, all.
  // (Before prepare() every rank holds every particle, all its own.)
  std::size_t owned_count() const { return distributed() ? halo_.owned() : particles_.size(); }
  // The particles of every rank (collective on a shared run).
  std::size_t global_count() const;
  // What a scene measures: this rank's own particles and the reductions over every rank's
  // (bed_view.hpp); alone, or before the run is shared out (every rank holding every
  // particle), the store itself with local reductions.
  BedView bed() const;
  const RankDomains& rank_domains() const { return domains_; }
  const HaloExchange& halo() const { return halo_; }
  const NeighbourList& neighbours() const { return neighbours_; }
  const WallReach& wall_reach() const { return wall_reach_; }
  const std::vector<Wall>& walls() const { return walls_; }
  const std::vector<MeshWall>& mesh_walls() const { return meshes_; }
  // The scene's walls as segments for pictures (written with the first particle snapshot); not
  // part of a checkpoint: the scene sets it again, and restore() keeps it.
  void set_outline(SceneOutline outline) { outline_ = std::move(outline); }
  const SceneOutline& outline() const { return outline_; }
  // This rank's sink (on a shared run its books hold the grains this rank removed).
  const OutletSink* outlet_sink() const { return sink_ ? &*sink_ : nullptr; }
  // The sink with every rank's books merged: the whole run's discharge (collective on a
  // shared run; alone, a copy of the sink); none without a sink.
  std::optional<OutletSink> merged_outlet_sink() const;
  // What the sink took after time `since`, of every rank (collective on a shared run); zero
  // without a sink. The books' sums, for a scene that needs no single event.
  struct SunkTally {
    double mass = 0.0;   // [kg]
    double count = 0.0;
    double last = 0.0;   // the time of the last one taken; `since` when none [s]
  };
  SunkTally sunk(double since = -std::numeric_limits<double>::infinity()) const;
  const SimulationBox& box() const { return box_; }
  const RunReport& report() const { return report_; }
  // Of every rank's own particles (collective on a shared run).
  double kinetic_energy() const;
  double max_speed() const;
  // The warning raised (once) when a contact grew stiffer than the time step allows with its
  // safety factor; empty if none. The engine prints nothing: the scene reports it. On a shared
  // run, the first rank's that raised one, naming that rank (collective).
  std::string spring_warning() const;
  // The particle-steps run so far.
  double particle_steps() const { return particle_steps_; }

 private:
  long steps_to(double t) const;  // whole steps until t is reached (stepper.hpp)
  bool shared() const { return settings_.ranks.shared(); }
  bool distributed() const { return shared() && halo_.initialised(); }  // particles shared out
  void rebuild_neighbours();
  // A shared run's rebuild: the captured particles removed, the sub-boxes re-cut when out of
  // balance, particles moved to their owners, re-sorted, their ghosts copied.
  void rebuild_shared(bool sink_due);
  void distribute();  // prepare() on a shared run: each rank keeps its own particles
  // Runs a guard check; on a shared run a failure on any rank stops every rank with its message.
  template <class Check>
  void guarded(Check&& check) const;
  void reset_forces();    // to the weight, no torque
  void compute_forces();  // adds the contact forces
  // The time step against the springs of the deepest current contacts (issue 5: the step
  // comes from the stiffest current spring): warns once when it exceeds their stable step,
  // stops the run through the guard when it exceeds their stability limit.
  void check_current_springs(const DeepestOverlap& pairs, const DeepestOverlap& walls);
  // One velocity Verlet step; unless `last`, its second half kick is left to the next step's
  // first pass over the particles (kick_pending_).
  void one_step(bool last);
  void finish_kick();  // the pending second half kick, its kinetic energy and the guard check
  std::string make_plan() const;
  void restore_prepared_state();            // from pending_, in prepare()
  std::size_t wall_history_stride() const;  // wall-history doubles per particle
  double fastest_wall_surface_speed() const;  // over the moving walls, at the particles [m/s]
  double bed_height() const;                  // extent of the particles along gravity [m]

  DemSettings settings_;
  SimulationBox box_;
  ParticleStore particles_;
  std::vector<Wall> walls_;
  std::vector<MeshWall> meshes_;
  SceneOutline outline_;
  std::optional<OutletSink> sink_;
  ContactLawChoice effective_law_;
  std::vector<std::string> skipped_;
  std::unique_ptr<ForceKernel> kernel_;
  NeighbourList neighbours_;
  WallReach wall_reach_;  // the walls each particle can touch until the next rebuild
  TimeStepChoice time_step_;
  BlowUpGuard guard_;
  RunReport report_{"DEM run"};
  std::string plan_;
  std::unique_ptr<DemCheckpoint> pending_;  // a restored run's state until prepare()
  bool prepared_ = false;
  bool rebuild_due_ = false;  // particles inserted or removed since the last step
  bool kick_pending_ = false;  // inside run_steps(): the last step's second half kick not done
  double time_ = 0.0;
  long step_ = 0;
  double particle_steps_ = 0.0;
  double particle_steps_before_ = 0.0;  // a continued run's earlier ones (not in run_seconds_)
  double run_seconds_ = 0.0;
  double checked_ratio_ = 0.0;  // overlap / radius whose springs were checked last
  std::string spring_warning_;
  RankDomains domains_;
  HaloExchange halo_;
  std::size_t rebalances_ = 0;
  // 1 for a free component, 0 for one the plane hold removes (hold_in_plane).
  Vec3 linear_free_ = Vec3::Ones();
  Vec3 angular_free_ = Vec3::Ones();
};

}  // namespace feedflow
