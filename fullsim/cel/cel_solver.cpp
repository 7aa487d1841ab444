#include "fullsim/cel/cel_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fullsim/cel/lagrangian_phase.hpp"
#include "models/core/errors.hpp"

namespace feedflow::cel {

CelSolver::CelSolver(const CelGrid& grid, const HypoplasticModel& model,
                     const CelOptions& options)
    : grid_(grid), model_(model), options_(options), remap_(options.remap, options.volume_fraction_cut) {
  if (grid_.axisymmetric() && grid_.origin.x() == 0.0 && options_.walls.left != WallCondition::free_slip)
    throw std::invalid_argument("axisymmetric CEL grid on the axis: its left face is the symmetry "
                                "line and must be free slip");
  cells_.resize(grid_.cell_count());
  nodes_.resize(grid_.node_count());
  mark_walls(place_walls(options_.rigid_walls, time_));
  refresh_nodes();
}

void CelSolver::mark_walls(const std::vector<PlacedWall>& walls) {
  if (options_.wall_cells == WallCells::staircase) {
    mark_wall_cells(grid_, walls, cells_);
    return;
  }
  std::vector<std::uint8_t> key;
  bool moving = false;
  for (const auto& w : options_.rigid_walls) {
    key.push_back(w.present(time_));
    moving = moving || (w.present(time_) && w.moving(time_));
  }
  if (moving || key != cut_walls_ || cut_.open.empty()) {
    cut_ = cut_cell_geometry(grid_, walls);
    cut_walls_ = moving ? std::vector<std::uint8_t>{} : key;
  }
  mark_cut_cells(cut_, cells_);
  remap_.set_cut_cells(&cut_);
}

void CelSolver::add_material(const MaterialBlock& b) {
  const double h = grid_.cell_size;
  const double grain_density = b.bulk_density * (1.0 + b.void_ratio);
  if (!(grain_density > 0.0) || !std::isfinite(grain_density))
    throw std::invalid_argument("material block: bulk density and void ratio must give a "
                                "positive grain density rho (1 + e)");
  const double known = remap_.grain_density();
  if (known > 0.0 && std::abs(grain_density - known) > 1e-9 * known) {
    std::ostringstream s;
    s << "material block: grain density rho (1 + e) = " << grain_density
      << " kg/m^3 differs from the earlier blocks' " << known
      << " kg/m^3 (one material per solver: its blocks may differ in void ratio only with the "
         "density that goes with it)";
    throw std::invalid_argument(s.str());
  }
  const HypoplasticParameters& hp = model_.parameters;
  remap_.set_grain_density(grain_density, {hp.e_d0, hp.h_s, hp.n});
  const auto walls = place_walls(options_.rigid_walls, time_);
  const bool cut = options_.wall_cells == WallCells::cut;
  for (std::size_t c = 0; c < grid_.cell_count(); ++c) {
    if (cells_.solid[c] || (!cut && distance_to_walls(walls, grid_.cell_centre(c)) < 0.0)) continue;
    const Eigen::Vector2d lo = grid_.cell_centre(c).array() - 0.5 * h;
    const double x0 = std::max(lo.x(), b.lower.x()), x1 = std::min(lo.x() + h, b.upper.x());
    const double wy = std::max(0.0, std::min(lo.y() + h, b.upper.y()) - std::max(lo.y(), b.lower.y()));
    if (!(x1 > x0) || !(wy > 0.0)) continue;
    // The overlap's share of the cell volume (r-weighted when axisymmetric: int r dr over
    // [x0, x1] is (x1 - x0) times the depth at its middle).
    const double overlap = (x1 - x0) * grid_.depth_at(0.5 * (x0 + x1)) * wy;
    // A cut cell takes the block's share of its open part.
    const double open = cells_.open_fraction[c];
    const double add =
        std::min(overlap * open / grid_.cell_volume(c), open - cells_.volume_fraction[c]);
    if (add <= 0.0) continue;
    const double m_add = add * grid_.cell_volume(c) * b.bulk_density;
    const double m_old = cells_.mass[c], vf_old = cells_.volume_fraction[c];
    cells_.stress[c] = (cells_.stress[c] * vf_old + b.stress * add) / (vf_old + add);
    cells_.void_ratio[c] = (cells_.void_ratio[c] * m_old + b.void_ratio * m_add) / (m_old + m_add);
    cells_.mass[c] = m_old + m_add;
    cells_.volume_fraction[c] = vf_old + add;
  }
  // Of the smallest cell (axisymmetric: the column at the axis).
  void_node_mass_ = std::max(void_node_mass_, kVoidNodeMassFraction * 0.25 * grid_.cell_volume(0) *
                                                  b.bulk_density);
  refresh_nodes();
}

void CelSolver::set_solid(std::size_t c) {
  cells_.solid[c] = kSolidFixed;
  cells_.volume_fraction[c] = 0.0;
  cells_.mass[c] = 0.0;
  cells_.stress[c].setZero();
  cells_.void_ratio[c] = 0.0;
  refresh_nodes();
}

void CelSolver::set_velocity(const NodeVector& v) {
  for (std::size_t a = 0; a < grid_.node_count(); ++a)
    nodes_.velocity[a] = nodes_.mass[a] > void_node_mass_ ? v : NodeVector::Zero();
  apply_node_constraints(nodes_);
}

void CelSolver::start_turning_frame() {
  options_.frame.start = time_;
  for (std::size_t a = 0; a < grid_.node_count(); ++a)
    if (nodes_.mass[a] > void_node_mass_)
      nodes_.velocity[a] -= options_.frame.carried_velocity(grid_.node_position(a));
  apply_node_constraints(nodes_);
}

void CelSolver::refresh_nodes() {
  assign_node_constraints(grid_, options_.walls, cells_, nodes_);
  lump_nodal_mass(grid_, cells_, nodes_);
}

void CelSolver::refresh_active_cells() {
  active_.clear();
  for (std::size_t c = 0; c < grid_.cell_count(); ++c)
    if (!cells_.solid[c] && cells_.mass[c] > 0.0 &&
        cells_.open_volume_fraction(c) > options_.min_volume_fraction)
      active_.push_back(c);
}

double CelSolver::gravity_factor(double t) const {
  const double ramp = options_.gravity_ramp_time;
  if (ramp <= 0.0 || t >= ramp) return 1.0;
  const double s = t / ramp;
  return s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);  // smooth step (Abaqus SMOOTH STEP)
}

CelStepReport CelSolver::step() {
  CelStepReport report;
  const auto walls = place_walls(options_.rigid_walls, time_);
  mark_walls(walls);
  refresh_active_cells();
  report.time_step = stable_time_step(grid_, active_, model_, options_.time_step, options_.forces,
                                      nodes_, cells_);
  if (report.time_step.failed_cell) {
    const std::size_t c = *report.time_step.failed_cell;
    std::ostringstream s;
    s << "CEL blow-up at step " << steps_ << ", t = " << time_ << " s, cell ("
      << grid_.cell_i(c) << ", " << grid_.cell_j(c) << "): no finite wave speed (void ratio "
      << cells_.void_ratio[c] << ", density " << cells_.density(c, grid_.cell_volume(c))
      << " kg/m^3, pressure " << -cells_.stress[c].trace() / 3.0 << " Pa)";
    if (dt_previous_ > 0.0)
      s << "; the last step was " << dt_previous_ << " s, try a time step below "
        << dt_previous_ * safer_courant() / options_.time_step.safety << " s ([cel] time_step_safety "
        << safer_courant() << ")";
    else
      s << " in the initial state (check the material block's density, void ratio and stress)";
    throw NumericalFailure(s.str());
  }
  const double dt = report.time_step.dt;
  report.dt = dt;
  guard_step_collapse(report);
  // The cap is not a stable step of the grid: a loose, stress-free fill on a fine grid runs at
  // it, and a hundredth of it is an ordinary step there.
  if (dt < options_.time_step.max_time_step) largest_dt_ = std::max(largest_dt_, dt);
  assemble_nodal_forces(grid_, active_, options_.forces,
                        gravity_factor(time_) * options_.frame.gravity(options_.gravity, time_),
                        cells_, nodes_);
  add_frame_forces(options_.frame, grid_, time_, void_node_mass_, nodes_);
  if (options_.settling_damping > 0.0)
    for (std::size_t a = 0; a < grid_.node_count(); ++a)
      nodes_.force[a] -= options_.settling_damping * nodes_.mass[a] * nodes_.velocity[a];
  report.dropped_momentum = advance_node_velocities(0.5 * (dt_previous_ + dt), void_node_mass_, nodes_);
  report.wall_forces = apply_wall_contact(grid_, walls, options_.contact, 0.5 * (dt_previous_ + dt),
                                          void_node_mass_, cells_, nodes_);
  const CellUpdateReport cu =
      update_cell_states(grid_, active_, model_, options_.substepping, options_.mixed_cells, dt,
                         nodes_, cells_);
  report.most_substeps = cu.most_substeps;
  report.unconverged_cells = cu.unconverged_cells;
  report.remap =
      remap_.remap(grid_, options_.walls, dt, steps_ % 2 == 0, void_node_mass_, cells_, nodes_);
  removed_mass_ += report.remap.removed_mass;
  discharge_.book(time_ + dt, report.remap.outflow_mass, report.remap.outflow_momentum);
  cell_updates_ += static_cast<long>(active_.size());
  time_ += dt;
  dt_previous_ = dt;
  ++steps_;
  guard(report);
  return report;
}

void CelSolver::run_until(double t_end) {
  while (time_ < t_end) step();
}

double CelSolver::safer_courant() const {
  return std::min(0.5 * options_.time_step.safety, TimeStepOptions{}.safety);  // half, and at most the default
}

void CelSolver::guard_step_collapse(const CelStepReport& report) const {
  // A hundredfold smaller step needs a 10^4 times stiffer cell (c_d grows about as sqrt(p)): no
  // gravity-driven bin, chute or drum loads its bulk so; measured, the settled runs take 1/5-1/10
  // of their first step, and the outlet-lip cell of a nearly frictionless wedge, crushed when the
  // walls were projected one after another at a corner, 1/1700.
  constexpr double kStepCollapse = 1e-2;
  if (active_.empty() || !(report.dt < kStepCollapse * largest_dt_)) return;
  const std::size_t c = report.time_step.limiting_cell;
  std::ostringstream s;
  s << "CEL time step collapsed at step " << steps_ << ", t = " << time_ << " s, cell (" << grid_.cell_i(c)
    << ", " << grid_.cell_j(c) << "): the step is " << report.dt << " s, below " << kStepCollapse
    << " of the largest of this run (" << largest_dt_ << " s); the cell (volume fraction "
    << cells_.volume_fraction[c] << ", void ratio " << cells_.void_ratio[c] << ", pressure "
    << -cells_.stress[c].trace() / 3.0 << " Pa) is being crushed by an unstable mode; rerun with [cel] "
    << "time_step_safety = " << safer_courant();
  throw NumericalFailure(s.str());
}

void CelSolver::guard(const CelStepReport& report) const {
  const auto fail = [&](std::size_t c, const std::string& what) {
    std::ostringstream s;
    s << "CEL blow-up at step " << steps_ << ", t = " << time_ << " s, cell (" << grid_.cell_i(c)
      << ", " << grid_.cell_j(c) << "): " << what << "; the step was " << report.dt
      << " s, try a time step below " << report.dt * safer_courant() / options_.time_step.safety
      << " s ([cel] time_step_safety " << safer_courant() << ")";
    throw NumericalFailure(s.str());
  };
  if (report.remap.max_outflow_fraction > 1.0)
    fail(report.time_step.limiting_cell, "a remap flux exceeds its donor cell (Courant > 1)");
  for (std::size_t c : active_) {
    if (!cells_.stress[c].allFinite() || !std::isfinite(cells_.void_ratio[c]) ||
        !std::isfinite(cells_.mass[c]))
      fail(c, "non-finite stress, void ratio or mass");
    for (std::size_t a : grid_.cell_nodes(c)) {
      const double v = nodes_.velocity[a].norm();
      if (!std::isfinite(v) || v > options_.max_speed) {
        std::ostringstream w;
        w << "node speed " << v << " m/s beyond the bound " << options_.max_speed << " m/s";
        fail(c, w.str());
      }
    }
  }
}

CelSolverState CelSolver::state() const {
  CelSolverState s;
  s.cells = cells_;
  s.cells.corner_force.clear();
  s.nodes = nodes_;
  s.void_node_mass = void_node_mass_;
  s.time = time_;
  s.dt_previous = dt_previous_;
  s.steps = steps_;
  s.cell_updates = cell_updates_;
  s.removed_mass = removed_mass_;
  s.settling_damping = options_.settling_damping;
  s.frame_start = options_.frame.start;
  for (const auto& w : options_.rigid_walls) {
    s.wall_removal_times.push_back(w.removal_time);
    s.wall_motion_starts.push_back(w.motion_start);
    s.wall_motion_ends.push_back(w.motion_end);
  }
  s.discharge = discharge_;
  return s;
}

void CelSolver::restore(const CelSolverState& s) {
  const std::size_t walls = options_.rigid_walls.size();
  if (s.cells.mass.size() != grid_.cell_count() || s.nodes.mass.size() != grid_.node_count() ||
      s.wall_removal_times.size() != walls || s.wall_motion_starts.size() != walls ||
      s.wall_motion_ends.size() != walls)
    throw std::invalid_argument("CEL state of another grid or wall set");
  cells_ = s.cells;
  cells_.corner_force.assign(grid_.cell_count() * kNodesPerCell, NodeVector::Zero());
  cells_.open_fraction.assign(grid_.cell_count(), 1.0);  // taken again from the walls below
  cut_walls_.clear();
  cut_.open.clear();
  nodes_ = s.nodes;
  void_node_mass_ = s.void_node_mass;
  time_ = s.time;
  dt_previous_ = s.dt_previous;
  steps_ = s.steps;
  cell_updates_ = s.cell_updates;
  removed_mass_ = s.removed_mass;
  options_.settling_damping = s.settling_damping;
  options_.frame.start = s.frame_start;
  for (std::size_t k = 0; k < walls; ++k) {
    options_.rigid_walls[k].removal_time = s.wall_removal_times[k];
    options_.rigid_walls[k].motion_start = s.wall_motion_starts[k];
    options_.rigid_walls[k].motion_end = s.wall_motion_ends[k];
  }
  discharge_ = s.discharge;
  mark_walls(place_walls(options_.rigid_walls, time_));
}

double CelSolver::total_mass() const {
  double m = 0.0;
  for (double x : cells_.mass) m += x;
  return m;
}

double CelSolver::overfilled_mass() const {
  const double rho_g = remap_.grain_density();
  if (rho_g <= 0.0) return 0.0;
  double m = 0.0;
  for (std::size_t c = 0; c < grid_.cell_count(); ++c) {
    if (cells_.mass[c] <= 0.0) continue;
    const double fits = cells_.volume_fraction[c] * grid_.cell_volume(c) * rho_g / (1.0 + cells_.void_ratio[c]);
    m += std::max(cells_.mass[c] - fits, 0.0);
  }
  return m;
}

NodeVector CelSolver::total_momentum() const {
  NodeVector p = NodeVector::Zero();
  for (std::size_t a = 0; a < grid_.node_count(); ++a) p += nodes_.mass[a] * nodes_.velocity[a];
  return p;
}

double CelSolver::kinetic_energy() const {
  double k = 0.0;
  for (std::size_t a = 0; a < grid_.node_count(); ++a)
    k += 0.5 * nodes_.mass[a] * nodes_.velocity[a].squaredNorm();
  return k;
}

NodeVector CelSolver::centre_of_mass() const {
  NodeVector s = NodeVector::Zero();
  double m = 0.0;
  for (std::size_t c = 0; c < grid_.cell_count(); ++c) {
    s += cells_.mass[c] * grid_.cell_centre(c);
    m += cells_.mass[c];
  }
  return m > 0.0 ? NodeVector(s / m) : s;
}

}  // namespace feedflow::cel
