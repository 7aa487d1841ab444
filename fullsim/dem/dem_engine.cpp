#include "fullsim/dem/dem_engine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "fullsim/dem/morton_order.hpp"
#include "fullsim/dem/ranks/merged_sink.hpp"
#include "models/core/errors.hpp"
#include "models/core/printf_format.hpp"

// force_kernel.cpp is built with Eigen's SSE code off but its 16-byte alignment kept
// (fullsim/CMakeLists.txt); a build whose flags give Eigen wider alignment must change both.
static_assert(EIGEN_MAX_STATIC_ALIGN_BYTES == 16, "Eigen alignment differs from force_kernel.cpp");

namespace feedflow {
DemEngine::DemEngine(DemSettings settings, SimulationBox box, ParticleStore particles)
    : settings_(std::move(settings)), box_(box), particles_(std::move(particles)) {}

DemEngine::DemEngine(DemSettings settings, DemCheckpoint checkpoint)
    : settings_(std::move(settings)),
      box_(checkpoint.box),
      particles_(std::move(checkpoint.particles)),
      walls_(std::move(checkpoint.walls)),
      sink_(std::move(checkpoint.sink)),
      time_(checkpoint.time),
      step_(checkpoint.step),
      particle_steps_(checkpoint.particle_steps),
      particle_steps_before_(checkpoint.particle_steps) {
  pending_ = std::make_unique<DemCheckpoint>(std::move(checkpoint));
  // Shared among ranks, the sink's books (what left before the checkpoint) are the first
  // rank's, so that their sum over the ranks is what the checkpoint booked.
  if (sink_ && shared() && settings_.ranks.rank() != 0)
    sink_ = OutletSink::restored(sink_->is_box(), sink_->lower_or_point(),
                                 sink_->upper_or_outward(), 0.0, {});
}

DemEngine::~DemEngine() = default;
DemEngine::DemEngine(DemEngine&&) noexcept = default;
DemEngine& DemEngine::operator=(DemEngine&&) noexcept = default;

double DemEngine::fastest_wall_surface_speed() const {
  double fastest = 0.0;
  auto scan = [&](const auto& wall) {
    if (!wall.moves()) return;
    for (const Vec3& x : particles_.position)
      fastest = std::max(fastest, wall.surface_velocity(x).norm());
  };
  for (const auto& w : walls_) scan(w);
  for (const auto& m : meshes_) scan(m);
  return fastest;
}

double DemEngine::bed_height() const {
  const double g = settings_.gravity.norm();
  if (g == 0.0 || particles_.size() == 0) return 0.0;
  const Vec3 down = settings_.gravity / g;
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const Vec3& x : particles_.position) {
    lowest = std::min(lowest, x.dot(down));
    highest = std::max(highest, x.dot(down));
  }
  return highest - lowest;
}

std::size_t DemEngine::wall_history_stride() const {
  // Per particle: one history per analytic wall, and per mesh wall kMaxContacts slots holding
  // the contact normal (3) and a history each.
  return walls_.size() * kernel_->history_size() +
         meshes_.size() * MeshWall::kMaxContacts * (3 + kernel_->history_size());
}

void DemEngine::restore_prepared_state() {
  const DemCheckpoint& c = *pending_;
  auto refuse = [](const std::string& what) {
    throw std::runtime_error("DEM restart refused: " + what +
                             " (restart with the settings of the checkpointed run)");
  };
  if (kernel_->name() != c.contact_law)
    refuse("the contact law is '" + kernel_->name() + "', the checkpoint's '" + c.contact_law + "'");
  if (time_step_.value != c.time_step)
    refuse(format("the time step is %.17g s, the checkpoint's %.17g s", time_step_.value,
                  c.time_step));
  if (settings_.gravity != c.gravity) refuse("gravity differs from the checkpoint's");
  if (c.neighbours.history_size() != kernel_->history_size())
    refuse(format("the law keeps %zu history doubles per contact, the checkpoint %zu",
                  kernel_->history_size(), c.neighbours.history_size()));
  if (particles_.wall_history_stride() != wall_history_stride())
    refuse("the wall history does not match the walls and the law");
  neighbours_ = c.neighbours;
  guard_.resume(c.guard_initial_energy, c.guard_energy_floor, c.guard_gravity_work,
                c.guard_wall_speed);
  pending_.reset();
}

void DemEngine::add_wall(Wall wall) {
  if (prepared_) throw InputError("", "dem.walls", "walls are added before the run is prepared");
  walls_.push_back(std::move(wall));
}

void DemEngine::add_mesh_wall(MeshWall mesh) {
  if (prepared_) throw InputError("", "dem.walls", "walls are added before the run is prepared");
  meshes_.push_back(std::move(mesh));
}

void DemEngine::set_outlet_sink(OutletSink sink) { sink_ = std::move(sink); }

void DemEngine::hold_in_plane(int axis) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("hold_in_plane: the axis is 0, 1 or 2");
  linear_free_ = Vec3::Ones();
  linear_free_[axis] = 0.0;
  angular_free_ = Vec3::Zero();
  angular_free_[axis] = 1.0;
  for (std::size_t i = 0; i < particles_.size(); ++i) {  // those already in the store
    particles_.velocity[i] = particles_.velocity[i].cwiseProduct(linear_free_);
    particles_.angular_velocity[i] = particles_.angular_velocity[i].cwiseProduct(angular_free_);
  }
}

std::uint32_t DemEngine::insert_particle(const Vec3& x, double radius, double density,
                                         double layer, const Vec3& given_velocity) {
  const Vec3 velocity = given_velocity.cwiseProduct(linear_free_);  // in the held plane, if any
  if (prepared_ && shared()) {
    // Every rank inserts the same particle, so the ids stay alike; the owner of its position
    // keeps it behind its own particles (the ghosts dropped until the next step's rebuild),
    // and every rank books its energy, as every rank holds the whole run's energy book.
    halo_.drop_ghosts(particles_);
    const std::uint32_t id = particles_.next_id();
    if (domains_.owner(x) == settings_.ranks.rank()) {
      particles_.add(x, radius, density, layer, velocity);
      particles_.force.back() = particles_.mass.back() * settings_.gravity;
    } else {
      particles_.set_next_id(id + 1);
    }
    halo_.own_all(particles_);
    const double mass = ParticleStore::sphere_mass(density, radius);
    guard_.add_inserted_energy(0.5 * mass * velocity.squaredNorm());
    rebuild_due_ = true;
    return id;
  }
  const std::uint32_t id = particles_.add(x, radius, density, layer, velocity);
  if (prepared_) {
    const std::size_t k = particles_.size() - 1;
    particles_.force[k] = particles_.mass[k] * settings_.gravity;
    guard_.add_inserted_energy(0.5 * particles_.mass[k] * velocity.squaredNorm());
    rebuild_due_ = true;
  }
  return id;
}

void DemEngine::remove_particles(const std::vector<char>& flagged) {
  if (flagged.size() != particles_.size())
    throw std::invalid_argument("DemEngine::remove_particles: one flag per particle expected");
  if (prepared_ && shared()) {
    // Each rank removes its own flagged particles; a ghost's flag is its owner's to set.
    std::vector<char> own(flagged.begin(),
                          flagged.begin() + static_cast<std::ptrdiff_t>(owned_count()));
    halo_.drop_ghosts(particles_);
    particles_.remove_flagged(own);
    halo_.own_all(particles_);
    rebuild_due_ = true;
    return;
  }
  particles_.remove_flagged(flagged);
  rebuild_due_ = prepared_;
}

void DemEngine::set_wall_removal_time(const std::string& name, double t) {
  for (auto& w : walls_)
    if (w.name() == name) {
      w.removed_at(t);
      return;
    }
  throw std::invalid_argument("DemEngine: no analytic wall named '" + name + "'");
}

void DemEngine::prepare(std::ostream& out) {
  if (prepared_) return;
  const DemParameters& dem = settings_.material;
  // Kernels whose parameters make them vanish are not run at all.
  effective_law_ = settings_.law;
  skipped_.clear();
  if (!effective_law_.rolling.is<NoRolling>() && dem.particle_particle.rolling_friction == 0.0 &&
      dem.particle_wall.rolling_friction == 0.0) {
    effective_law_.rolling = contact_part<NoRolling>;
    skipped_.push_back("rolling kernel skipped: mu_r = 0 in the P-P and P-W sets");
  }
  const bool rolling_reads_kt = effective_law_.rolling.visit(
      [](auto r) { return decltype(r)::type::kReadsTangentialStiffness; });
  if (!effective_law_.tangential.is<NoTangential>() && dem.particle_particle.friction == 0.0 &&
      dem.particle_wall.friction == 0.0 && !rolling_reads_kt) {
    effective_law_.tangential = contact_part<NoTangential>;
    skipped_.push_back("tangential kernel skipped: mu = 0 in the P-P and P-W sets");
  }
  if (effective_law_.cohesion.is<NoCohesion>())
    skipped_.push_back("cohesion: none (normal force clipped at zero, no contact pulls)");
  kernel_ = make_force_kernel(effective_law_, dem);

  // A run that emptied (a hopper drained to its last sphere) and was checkpointed so has no
  // particles left: its grid and step are the material's spheres'.
  double rmax = settings_.ranks.max(particles_.max_radius());
  if (!(rmax > 0.0) && particles_.size() == 0) rmax = settings_.material.particle.radius;
  if (!(rmax > 0.0)) throw InputError("", "dem.particles", "no particles, or a zero radius");
  const double cutoff = 2.0 * rmax * (1.0 + settings_.skin_fraction);
  for (int a = 0; a < 3; ++a)
    if (box_.periodic[a] && box_.length()[a] < 2.0 * cutoff)
      throw InputError("", "dem.box",
                       format("periodic axis %c is %.4g m long, shorter than twice the neighbour "
                              "cutoff %.4g m",
                              "xyz"[a], box_.length()[a], cutoff));

  const StiffestSpring springs =
      design_springs(dem, effective_law_, effective_law_, settings_.time_step.design_overlap);
  const StableTimeStep stable = stable_time_step(dem, springs, settings_.time_step);
  const double requested = settings_.requested_time_step > 0.0 || settings_.stable_step_fraction == 1.0
                               ? settings_.requested_time_step
                               : settings_.stable_step_fraction * stable.value;
  time_step_ = choose_time_step(stable, requested, settings_.force_time_step);

  guard_ = BlowUpGuard(settings_.guard, stable.value);
  checked_ratio_ = settings_.time_step.design_overlap;  // the design springs hold up to here

  const double v_design = settings_.time_step.max_velocity;
  const double mass = particles_.total_mass();
  const double v_wall = fastest_wall_surface_speed();
  // Walls that move feed energy: allow every grain carried at the fastest wall surface speed
  // and dropped over the bed's height.
  const double v_fed = v_wall > 0.0 ? v_wall + std::sqrt(2.0 * settings_.gravity.norm() * bed_height()) : 0.0;
  if (pending_) {
    // A restored run keeps its list, forces and energy book as they were. Walls set moving
    // since the checkpoint was taken (a drum started after settling: the book's floor was set
    // with still walls) raise its floor; a book that already allows for moving walls is kept
    // as it is, not re-taken from the bed at the restart (a tilted bed is taller than the one
    // the uninterrupted run took it from, and the continued run would differ from it).
    restore_prepared_state();
    // Within the skin of where they stand now: they stand within half of it from the restored
    // list's positions, and move at most half of it more before its next rebuild. Shared
    // among ranks, every rank read the whole checkpoint: each keeps its share, and the list
    // is rebuilt with the restored contacts' history carried over by their id pairs.
    if (shared()) distribute();
    else wall_reach_.update(particles_, walls_, meshes_, neighbours_.skin());
    if (v_wall > 0.0 && guard_.wall_speed() == 0.0)
      guard_.allow_moving_walls(0.5 * mass * (v_design * v_design + v_fed * v_fed), v_wall);
  } else {
    neighbours_ = NeighbourList(settings_.skin_fraction * rmax, kernel_->history_size());
    particles_.set_wall_history_stride(wall_history_stride());
    if (shared()) distribute();
    else rebuild_neighbours();
    reset_forces();
    compute_forces();
    // Floor: every particle moving at the design speed of the time step (initial overlaps may
    // release elastic energy the guard cannot book), plus what moving walls feed.
    guard_.start(kinetic_energy(), 0.5 * mass * (v_design * v_design + v_fed * v_fed), v_wall);
  }
  plan_ = make_plan();
  if (shared()) {
    const double mine = static_cast<double>(owned_count());
    plan_ += format("  ranks: %d, each owning the particles of its sub-box (recursive coordinate "
                    "bisection by particle count, cut again above %.3g x the mean) and ghost "
                    "copies of its neighbours' within %.4g m; particles per rank %.0f-%.0f\n",
                    settings_.ranks.size(), settings_.rebalance_above,
                    2.0 * rmax + neighbours_.skin(), -settings_.ranks.max(-mine),
                    settings_.ranks.max(mine));
  }
  out << plan_;
  if (!time_step_.warning.empty()) out << time_step_.warning << '\n';
  prepared_ = true;
}

void DemEngine::distribute() {
  // Every rank holds every particle: each keeps a share (every size-th slot), the domains are
  // cut by those shares' counts, and the particles go to their owners.
  const DemRanks& ranks = settings_.ranks;
  std::vector<char> others(particles_.size(), 0);
  for (std::size_t k = 0; k < others.size(); ++k)
    others[k] = static_cast<int>(k % static_cast<std::size_t>(ranks.size())) != ranks.rank();
  particles_.remove_flagged(others);
  domains_ = RankDomains::bisect(particles_.position, particles_.size(), box_, ranks);
  rebuild_shared(false);
}

void DemEngine::rebuild_shared(bool sink_due) {
  const DemRanks& ranks = settings_.ranks;
  halo_.drop_ghosts(particles_);
  if (sink_due && sink_ && sink_->remove(particles_, time_) > 0) halo_.own_all(particles_);
  const double mine = static_cast<double>(particles_.size());
  const double most = ranks.max(mine), all = ranks.sum(mine);
  if (most > settings_.rebalance_above * all / ranks.size()) {
    domains_ = RankDomains::bisect(particles_.position, particles_.size(), box_, ranks);
    ++rebalances_;
  }
  halo_.migrate(particles_, neighbours_, domains_, ranks);
  const double rmax = ranks.max(particles_.max_radius());
  if (settings_.sort_every > 0 && neighbours_.rebuild_count() % settings_.sort_every == 0)
    particles_.permute(morton_order(particles_.position, box_, 2.0 * rmax + neighbours_.skin()));
  halo_.build_ghosts(particles_, domains_, 2.0 * rmax + neighbours_.skin(), ranks);
  neighbours_.rebuild(particles_, box_, halo_.owned());
  wall_reach_.update(particles_, walls_, meshes_, neighbours_.skin());
}

template <class Check>
void DemEngine::guarded(Check&& check) const {
  if (!shared()) {
    check();
    return;
  }
  std::optional<std::string> failure;
  try {
    check();
  } catch (const NumericalFailure& e) {
    failure = e.what();
  }
  if (auto agreed = settings_.ranks.agree_on_failure(failure)) throw NumericalFailure(*agreed);
}

std::optional<OutletSink> DemEngine::merged_outlet_sink() const {
  if (!sink_ || !shared()) return sink_;
  return merge_sink_books(*sink_, settings_.ranks);
}

DemEngine::SunkTally DemEngine::sunk(double since) const {
  std::vector<double> tally{0.0, 0.0};
  double last = since;
  if (sink_ && since == -std::numeric_limits<double>::infinity())
    tally = {sink_->removed_mass(), static_cast<double>(sink_->removed_count())};
  else if (sink_)
    for (const SinkEvent& e : sink_->events())
      if (e.time > since) {
        tally[0] += e.mass;
        tally[1] += 1.0;
      }
  if (sink_ && !sink_->events().empty()) last = std::max(last, sink_->events().back().time);
  if (shared()) {
    settings_.ranks.sum(tally);
    last = settings_.ranks.max(last);
  }
  return {tally[0], tally[1], last};
}

std::size_t DemEngine::global_count() const {
  if (!distributed()) return particles_.size();
  return static_cast<std::size_t>(settings_.ranks.sum(static_cast<double>(owned_count())));
}

std::string DemEngine::spring_warning() const {
  if (!shared()) return spring_warning_;
  const auto agreed = settings_.ranks.agree_on_failure(
      spring_warning_.empty() ? std::nullopt : std::optional<std::string>(spring_warning_));
  return agreed.value_or(std::string());
}

BedView DemEngine::bed() const {
  return distributed() ? BedView(particles_, owned_count(), settings_.ranks)
                       : BedView(particles_, particles_.size(), DemRanks::one());
}

void DemEngine::rebuild_neighbours() {
  if (shared()) {
    rebuild_shared(false);
    return;
  }
  if (settings_.sort_every > 0 && neighbours_.rebuild_count() % settings_.sort_every == 0) {
    const double cell = 2.0 * particles_.max_radius() + neighbours_.skin();
    particles_.permute(morton_order(particles_.position, box_, cell));
  }
  neighbours_.rebuild(particles_, box_);
  wall_reach_.update(particles_, walls_, meshes_, neighbours_.skin());
}

void DemEngine::reset_forces() {
  for (std::size_t i = 0; i < owned_count(); ++i) {
    particles_.force[i] = particles_.mass[i] * settings_.gravity;
    particles_.torque[i].setZero();
  }
}

void DemEngine::compute_forces() {
  const std::size_t n = particles_.size();
  ForceContext c{particles_, neighbours_, box_,   walls_, meshes_,
                 time_,      time_step_.value, n >= settings_.parallel_from};
  if (wall_reach_.size() == n) c.wall_reach = wall_reach_.data();
  c.owned = owned_count();
  DeepestOverlap pairs, walls;
  // One parallel region for the pair and wall loops; the walls phase is the time one thread
  // spent on its share of the wall contacts, the pairs phase the rest.
  const auto start = std::chrono::steady_clock::now();
  double wall_seconds = 0.0;
  kernel_->add_contact_forces(c, pairs, walls, wall_seconds);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report_.add_phase_time("pairs", seconds - wall_seconds);
  report_.add_phase_time("walls", wall_seconds);
  if (shared()) {
    auto scope = report_.time("exchange");
    halo_.reverse(particles_, settings_.ranks);
  }
  guarded([&] {
    guard_.check_overlap(pairs.ratio >= walls.ratio ? pairs : walls, particles_, step_);
    check_current_springs(pairs, walls);
  });
}

void DemEngine::check_current_springs(const DeepestOverlap& pairs, const DeepestOverlap& walls) {
  // Every law's springs stiffen with the overlap, and the design springs of prepare() hold up
  // to the design overlap; the springs are looked at again only when the deepest contact is
  // 5 % deeper than the deepest looked at so far (a few times in a run, not every step).
  const double deepest = std::max(pairs.ratio, walls.ratio);
  if (!(deepest > 1.05 * checked_ratio_)) return;
  checked_ratio_ = deepest;
  const StiffestSpring now =
      current_springs(settings_.material, effective_law_, pairs.ratio, walls.ratio);
  if (now.empty()) return;
  const StableTimeStep live = stable_time_step(settings_.material, now, settings_.time_step);
  const DeepestOverlap& at = pairs.ratio >= walls.ratio ? pairs : walls;
  guard_.check_spring(time_step_.value, now.period(), now.description(), live.value, particles_,
                      at.slot, step_);
  if (spring_warning_.empty() && time_step_.value > live.value) {
    spring_warning_ = format("warning: at step %ld the deepest contacts (P-P %.3g R, P-W %.3g R) "
                             "are stiffer than the time step allows: %.4g s exceeds their stable "
                             "step %.4g s (%s); the run goes on, watched by the blow-up guard",
                             step_, pairs.ratio, walls.ratio, time_step_.value, live.value,
                             now.description().c_str());
  }
}

void DemEngine::one_step(bool last) {
  const double dt = time_step_.value;
  const std::size_t n = owned_count();
  ParticleStore& p = particles_;
  const Vec3 g = settings_.gravity;
  // The second half kick of the step before (when it was left pending) and the first half
  // kick and drift of this one, in one pass over the particles; the forces are then reset to
  // the weight, and the largest displacement since the last rebuild is taken on the way.
  // Per particle the operations and their order are those of two separate passes.
  const bool finish_before = kick_pending_;
  const Vec3 linear = linear_free_, angular = angular_free_;
  double moved2 = 0.0, kinetic = 0.0, gravity_work = 0.0;
  {
    auto scope = report_.time("integration");
    const std::vector<Vec3>& reference = neighbours_.reference_positions();
    const bool same_slots = reference.size() == p.size();
#pragma omp parallel for schedule(static) reduction(max : moved2) \
    reduction(+ : kinetic, gravity_work) if (n >= settings_.parallel_from)
    for (std::size_t i = 0; i < n; ++i) {
      if (finish_before) {
        gravity_work += dt * p.mass[i] * g.dot(p.velocity[i]);  // at the half step
        p.velocity[i] += (0.5 * dt / p.mass[i]) * p.force[i].cwiseProduct(linear);
        p.angular_velocity[i] += (0.5 * dt / p.inertia[i]) * p.torque[i].cwiseProduct(angular);
        kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm() +
                   0.5 * p.inertia[i] * p.angular_velocity[i].squaredNorm();
      }
      p.velocity[i] += (0.5 * dt / p.mass[i]) * p.force[i].cwiseProduct(linear);
      p.angular_velocity[i] += (0.5 * dt / p.inertia[i]) * p.torque[i].cwiseProduct(angular);
      p.position[i] += dt * p.velocity[i];
      p.force[i] = p.mass[i] * g;
      p.torque[i].setZero();
      if (same_slots) moved2 = std::max(moved2, (p.position[i] - reference[i]).squaredNorm());
    }
    if (!same_slots) moved2 = std::numeric_limits<double>::infinity();
    for (auto& w : walls_) w.advance(dt);
    for (auto& m : meshes_) m.advance(dt);
  }
  // A shared run sums what the guard and the rebuild need over the ranks in one reduction:
  // kinetic energy, gravity work, the particles the sink captures, the count and the ranks
  // with a particle moved past half the skin or particles inserted or removed.
  const double half_skin = 0.5 * neighbours_.skin();
  double captured = 0.0, count = static_cast<double>(n), moved_far = 0.0;
  if (shared()) {
    auto scope = report_.time("exchange");
    if (sink_)
      for (std::size_t i = 0; i < n; ++i) captured += sink_->captures(p.position[i]) ? 1.0 : 0.0;
    std::vector<double> sums{kinetic, gravity_work, captured, count,
                             moved2 > half_skin * half_skin || rebuild_due_ ? 1.0 : 0.0};
    settings_.ranks.sum(sums);
    kinetic = sums[0];
    gravity_work = sums[1];
    captured = sums[2];
    count = sums[3] - sums[2];
    moved_far = sums[4];
  }
  if (finish_before) {
    kick_pending_ = false;
    guard_.add_gravity_work(gravity_work);
    guarded([&] { guard_.check_state(particles_, kinetic, step_); });
  }
  time_ += dt;
  ++step_;
  if (shared()) {
    const bool rebuild = captured > 0.0 || moved_far > 0.0;
    if (rebuild) {
      auto scope = report_.time("neighbours");
      rebuild_shared(captured > 0.0);
    } else {
      auto scope = report_.time("exchange");
      halo_.forward(particles_, settings_.ranks);
    }
  } else {
    auto scope = report_.time("neighbours");
    const bool removed = sink_ && sink_->remove(particles_, time_) > 0;
    if (removed || rebuild_due_ || moved2 > half_skin * half_skin) rebuild_neighbours();
    count = static_cast<double>(particles_.size());
  }
  rebuild_due_ = false;
  compute_forces();
  particle_steps_ += count;
  if (last) finish_kick();
  else kick_pending_ = true;
}

void DemEngine::finish_kick() {
  const double dt = time_step_.value;
  const std::size_t m = owned_count();
  ParticleStore& p = particles_;
  double kinetic = 0.0, gravity_work = 0.0;
  {
    auto scope = report_.time("integration");
    const Vec3 g = settings_.gravity;
    const Vec3 linear = linear_free_, angular = angular_free_;
#pragma omp parallel for schedule(static) reduction(+ : kinetic, gravity_work) \
    if (m >= settings_.parallel_from)
    for (std::size_t i = 0; i < m; ++i) {
      gravity_work += dt * p.mass[i] * g.dot(p.velocity[i]);  // at the half step
      p.velocity[i] += (0.5 * dt / p.mass[i]) * p.force[i].cwiseProduct(linear);
      p.angular_velocity[i] += (0.5 * dt / p.inertia[i]) * p.torque[i].cwiseProduct(angular);
      kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm() +
                 0.5 * p.inertia[i] * p.angular_velocity[i].squaredNorm();
    }
  }
  if (shared()) {
    std::vector<double> sums{kinetic, gravity_work};
    settings_.ranks.sum(sums);
    kinetic = sums[0];
    gravity_work = sums[1];
  }
  kick_pending_ = false;
  guard_.add_gravity_work(gravity_work);
  guarded([&] { guard_.check_state(particles_, kinetic, step_); });
}

void DemEngine::run_steps(long steps) {
  if (!prepared_) {
    std::ostringstream silent;
    prepare(silent);
  }
  const auto start = std::chrono::steady_clock::now();
  // Between two steps of this call the second half kick waits for the next step's first pass;
  // the last step finishes its own, so the state is whole between calls.
  for (long s = 0; s < steps; ++s) one_step(s + 1 == steps);
  run_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

long DemEngine::steps_to(double t) const {
  const double x = (t - time_) / time_step_.value;
  if (!(x > 0.0)) return 0;
  if (!std::isfinite(x)) return kUnbounded;
  // A time within a quarter step of a step is that step: the summed time drifts from the
  // step grid by round-off only.
  const double nearest = std::round(x);
  return static_cast<long>(std::abs(x - nearest) < 0.25 ? nearest : std::ceil(x));
}

long DemEngine::advance_to(double t, long max_steps) {
  if (!prepared_) {
    std::ostringstream silent;
    prepare(silent);
  }
  const long steps = std::min(steps_to(t), max_steps);
  if (steps > 0) run_steps(steps);
  return std::max(0L, steps);
}

double DemEngine::whole_steps(double duration, StepRounding rounding) const {
  const double dt = time_step_.value;
  const double steps = rounding == StepRounding::up ? std::ceil(duration / dt - 1e-9)
                                                    : std::max(1.0, std::round(duration / dt));
  return steps * dt;
}

double DemEngine::max_speed() const {
  double v2 = 0.0;
  for (std::size_t k = 0; k < owned_count(); ++k)
    v2 = std::max(v2, particles_.velocity[k].squaredNorm());
  return std::sqrt(settings_.ranks.max(v2));
}

double DemEngine::kinetic_energy() const {
  const double mine = particles_.kinetic_energy(owned_count());
  return distributed() ? settings_.ranks.sum(mine) : mine;
}

}  // namespace feedflow
