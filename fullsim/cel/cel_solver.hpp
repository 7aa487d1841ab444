#pragma once
// The plane-strain CEL solver: one step is the time-step pass (per-cell wave-speed bound), the
// Lagrangian phase (forces, central-difference velocities, hypoplastic update per active cell)
// and the donor-cell remap back to the fixed grid, followed by the blow-up guard
// (models.md 2.2-2.5, 5.2). Gravity may be ramped by a smooth step, as the seed deck did.
// Rigid walls at any angle act on the nodes after the velocity update (wall_contact, 2.6 C1);
// mass leaving through outflow box faces is booked in the discharge ledger (2.7).
#include <cstddef>
#include <limits>
#include <vector>

#include "fullsim/cel/box_walls.hpp"
#include "fullsim/cel/cel_fields.hpp"
#include "fullsim/cel/cut_cells.hpp"
#include "fullsim/cel/discharge_ledger.hpp"
#include "fullsim/cel/lagrangian_phase.hpp"
#include "fullsim/cel/nodal_forces.hpp"
#include "fullsim/cel/remap_phase.hpp"
#include "fullsim/cel/rigid_wall.hpp"
#include "fullsim/cel/stable_time_step.hpp"
#include "fullsim/cel/turning_frame.hpp"
#include "fullsim/cel/wall_contact.hpp"
#include "models/hypoplastic/material_point_integrator.hpp"

namespace feedflow::cel {

struct CelOptions {
  ForceOptions forces{};
  TimeStepOptions time_step{};
  SubsteppingOptions substepping{};
  BoxWalls walls{};
  std::vector<RigidWall> rigid_walls{};  // signed-distance walls with Coulomb friction
  WallContactOptions contact{};
  RemapOptions remap{};  // advection order of the cell state, material flux (PLIC)
  MixedCellRule mixed_cells = MixedCellRule::equal_strain_rate;  // models.md 2.3 item 7
  WallCells wall_cells = WallCells::staircase;  // how inclined walls cut the grid (cut_cells.hpp)
  NodeVector gravity = NodeVector(0.0, -9.81);  // [m/s^2], in the laboratory
  TurningFrame frame{};  // the laboratory unless started (a drum: the frame of its shell)
  double gravity_ramp_time = 0.0;  // smooth step 0 -> 1 over this time [s]; 0: at once
  // Mass-proportional damping -alpha m v for the gravity (settling) phase only, as dynamic
  // relaxation [1/s]; 0: off (default). Not physical: a run that uses it says so.
  double settling_damping = 0.0;
  double min_volume_fraction = 1e-6;   // cells above it (and not solid) are active
  double volume_fraction_cut = 1e-12;  // the remap empties cells below it (mass booked)
  double max_speed = 50.0;             // blow-up guard on nodal speed [m/s]
};

// A rectangle of material: bulk density, void ratio and an initial stress (tension positive).
struct MaterialBlock {
  Eigen::Vector2d lower = Eigen::Vector2d::Zero();  // [m]
  Eigen::Vector2d upper = Eigen::Vector2d::Zero();  // [m]
  double bulk_density = 0.0;                         // [kg/m^3]
  double void_ratio = 0.0;                           // [-]
  Eigen::Matrix3d stress = -10.0 * Eigen::Matrix3d::Identity();  // seed deck: -10 Pa I
};

// Everything a step depends on besides the grid, model and options: what a checkpoint holds so
// that a restarted run continues bit-identically.
struct CelSolverState {
  CellFields cells;   // corner_force is scratch and not kept
  NodeFields nodes;
  double void_node_mass = 0.0;
  double time = 0.0;
  double dt_previous = 0.0;
  long steps = 0;
  long cell_updates = 0;
  double removed_mass = 0.0;
  double settling_damping = 0.0;
  double frame_start = std::numeric_limits<double>::infinity();  // TurningFrame::start [s]
  std::vector<double> wall_removal_times, wall_motion_starts, wall_motion_ends;  // per rigid wall
  DischargeLedger discharge;
};

struct CelStepReport {
  double dt = 0.0;
  TimeStepChoice time_step{};
  int most_substeps = 0;
  int unconverged_cells = 0;
  RemapReport remap{};
  NodeVector dropped_momentum = NodeVector::Zero();  // on void nodes in the Lagrangian phase
  std::vector<NodeVector> wall_forces{};  // on the material, per rigid wall present [N/m]
};

class CelSolver {
 public:
  CelSolver(const CelGrid& grid, const HypoplasticModel& model, const CelOptions& options);

  // Adds material to the cells the block overlaps (volume fraction = overlapped area share),
  // except cells whose centre lies inside a rigid wall present at the current time (staircase
  // walls), or to the open part of the cells it overlaps (cut cells).
  void add_material(const MaterialBlock& block);
  void set_solid(std::size_t cell);
  // Gives every node that carries mass the velocity v.
  void set_velocity(const NodeVector& v);

  // Scene events: a wall removed or set moving at a time, dynamic relaxation switched off.
  RigidWall& rigid_wall(std::size_t k) { return options_.rigid_walls.at(k); }
  void set_settling_damping(double alpha) { options_.settling_damping = alpha; }
  // From now on the solver works in options().frame, turning at its angular velocity: the
  // material's velocities become relative to the frame (v - omega x (x - c)).
  void start_turning_frame();
  const TurningFrame& frame() const { return options_.frame; }

  // The state for a checkpoint, and its restoration (grid sizes and wall count must match).
  CelSolverState state() const;
  void restore(const CelSolverState& state);

  // One step; throws NumericalFailure (naming step, time, cell and a safer dt) on blow-up.
  CelStepReport step();
  // Steps until time t_end (the last step is not shortened).
  void run_until(double t_end);

  const CelGrid& grid() const { return grid_; }
  const CellFields& cells() const { return cells_; }
  const NodeFields& nodes() const { return nodes_; }
  const std::vector<std::size_t>& active_cells() const { return active_; }
  const CelOptions& options() const { return options_; }
  double time() const { return time_; }
  long step_count() const { return steps_; }
  double last_dt() const { return dt_previous_; }
  long cell_updates() const { return cell_updates_; }

  double total_mass() const;          // [kg/m]
  // Mass the cells hold beyond the density their void ratio allows, rho_g / (1 + e): what the
  // walls' staircase cells carry on (remap_phase.hpp) and overpacked cells [kg/m]; 0 without a
  // grain density.
  double overfilled_mass() const;
  NodeVector total_momentum() const;  // nodal [kg m/s /m]
  double kinetic_energy() const;      // nodal [J/m]
  double removed_mass() const { return removed_mass_; }  // below the volume-fraction cut
  const DischargeLedger& discharge() const { return discharge_; }  // through outflow faces
  NodeVector centre_of_mass() const;  // [m]

 private:
  void refresh_active_cells();
  // Marks the cells the walls placed at the current time shut (staircase) or cut (cut cells: the
  // geometry is taken again when a wall moves, or appears or goes).
  void mark_walls(const std::vector<PlacedWall>& walls);
  void refresh_nodes();
  double gravity_factor(double t) const;
  // The Courant number a blow-up message advises: half the one used, at most the default.
  double safer_courant() const;
  void guard(const CelStepReport& report) const;
  // Stops a run whose step has collapsed (kStepCollapse of the largest step of the run below the
  // cap): a cell crushed by an unstable mode, which would otherwise crawl on at a step that keeps
  // shrinking.
  void guard_step_collapse(const CelStepReport& report) const;

  CelGrid grid_;
  HypoplasticModel model_;
  CelOptions options_;
  CellFields cells_;
  NodeFields nodes_;
  RemapPhase remap_;
  CutCellGeometry cut_;
  std::vector<std::uint8_t> cut_walls_;  // which walls cut_ was taken for (empty: not yet)
  std::vector<std::size_t> active_;
  double void_node_mass_ = 0.0;
  double time_ = 0.0;
  double dt_previous_ = 0.0;
  double largest_dt_ = 0.0;  // of the steps below the cap in this process (not a checkpoint's run)
  long steps_ = 0;
  long cell_updates_ = 0;
  double removed_mass_ = 0.0;
  DischargeLedger discharge_;
};

}  // namespace feedflow::cel
