#pragma once
// The pair and wall loops of one composed contact law, with the kinematics of models.md 4.1.
// OpenMP without atomics: each thread owns a block of rows and writes the forces of its own
// block only; reactions on bodies of other blocks are queued and applied by their owner after
// a barrier, in thread order, so a run is deterministic for a given thread count. Wall
// contacts (wall_contact_forces.hpp) touch one particle each and write directly.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "fullsim/dem/contact_batch.hpp"
#include "fullsim/dem/force_kernel.hpp"
#include "fullsim/dem/wall_contact_forces.hpp"

namespace feedflow {

template <class Law>
class LawForces final : public ForceKernel {
 public:
  static constexpr std::size_t kHistory = Law::kHistorySize;

  explicit LawForces(const DemParameters& dem)
      : particle_particle_(dem.particle_particle), walls_(dem.particle_wall) {}

  std::string name() const override { return Law::name(); }
  std::size_t history_size() const override { return kHistory; }

  void add_contact_forces(ForceContext& c, DeepestOverlap& pairs, DeepestOverlap& walls,
                          double& wall_seconds) override {
    const bool any_wall = !c.walls.empty() || !c.meshes.empty();
    walls = {};
    wall_seconds = 0.0;
    pairs = contact_forces(c, any_wall ? &walls : nullptr, wall_seconds);
  }

  // The pair loop, and with `walls` also the wall contacts: each thread runs those of its own
  // rows once their pair forces and queued reactions are in (the order of the sums on each
  // particle is that of the two loops run one after the other). `wall_seconds`: thread 0's
  // time on its walls. flatten: the composed law's parts (and Eigen's small-vector helpers) are
  // inlined into the loop; left to the inliner's size limits they stayed out-of-line calls.
  [[gnu::flatten]] DeepestOverlap contact_forces(ForceContext& c, DeepestOverlap* walls,
                                                 double& wall_seconds) {
    ParticleStore& p = c.particles;
    const std::size_t n = p.size();
#ifdef _OPENMP
    const int threads = c.parallel ? omp_get_max_threads() : 1;
#else
    const int threads = 1;
#endif
    // Thread t owns a block of consecutive rows [bound_t, bound_t+1): it adds into the
    // particles' arrays for every body in its block, and queues the reaction on a body of
    // another block (few, the slots being Morton-ordered); after a barrier each thread applies
    // the queued reactions on its block in thread order. No atomics, no race, and
    // deterministic for a thread count. The blocks hold equal shares of listed entries plus
    // rows (a bed's lower, compressed half has more entries than its top).
    const auto nt = static_cast<std::size_t>(threads);
    own_.resize(nt);
    std::vector<std::size_t> bound(nt + 1, n);
    bound[0] = 0;
    const std::uint32_t* row_first = c.neighbours.first.data();
    const double work = static_cast<double>(row_first[n]) + static_cast<double>(n);
    for (std::size_t t = 1; t < nt; ++t) {
      const double share = work * static_cast<double>(t) / static_cast<double>(nt);
      std::size_t lo = bound[t - 1], hi = n;  // first row whose prefix work reaches the share
      while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (static_cast<double>(row_first[mid]) + static_cast<double>(mid) < share) lo = mid + 1;
        else hi = mid;
      }
      bound[t] = lo;
    }
    const Vec3* x = p.position.data();
    const Vec3* v = p.velocity.data();
    const Vec3* w = p.angular_velocity.data();
    Vec3* force = p.force.data();
    Vec3* torque = p.torque.data();
    const double* rad = p.radius.data();
    const double* mass = p.mass.data();
    const double* inertia = p.inertia.data();
    const std::uint32_t* first = c.neighbours.first.data();
    const std::uint32_t* partner = c.neighbours.partner.data();
    double* history = c.neighbours.history.data();
    const SimulationBox box = c.box;
    const double dt = c.dt;
    // A bed of equal spheres (one species) has the same R*, m* and I* for every pair: taken once
    // here by the very same expressions, so the results stay bit for bit those of the general
    // loop, without three divisions per contact.
    const UniformBodies uniform = uniform_bodies(p, c.neighbours.rebuild_count());
    const int lane_bits = std::min(c.max_lane_bits, lane_bits_available());

#pragma omp parallel num_threads(threads) if (threads > 1)
    {
#ifdef _OPENMP
      const auto tid = static_cast<std::size_t>(omp_get_thread_num());
#else
      const std::size_t tid = 0;
#endif
      const std::size_t begin = bound[tid], end = bound[tid + 1];
      std::vector<Reaction>& queue = own_[tid].queue;
      queue.clear();
      DeepestOverlap worst;
      // Two passes over batches of entries: the first finds the touching pairs and their
      // kinematics, the law then runs over the whole batch as one vectorised loop
      // (ContactBatch), and the forces are added lane by lane in entry order. Row i's own force
      // and torque are summed in a local and added when its row is done, as a single pass
      // would, so the sums are the same bit for bit.
      Batch& b = own_[tid].batch;
      std::size_t row = begin;  // the row whose force is being summed
      Vec3 fi = Vec3::Zero(), ti = Vec3::Zero();
      auto run_batch = [&]() {
        b.evaluate_with(lane_bits, particle_particle_, dt);
        for (std::size_t k = 0; k < b.count; ++k) {
          if (b.i[k] != row) {
            force[row] += fi;
            torque[row] += ti;
            fi.setZero();
            ti.setZero();
            row = b.i[k];
          }
          double* h = history + static_cast<std::size_t>(b.entry[k]) * kHistory;
          for (std::size_t q = 0; q < kHistory; ++q) h[q] = b.history[q][k];
          const Vec3 f(b.fx[k], b.fy[k], b.fz[k]);
          const Vec3 tj(b.tjx[k], b.tjy[k], b.tjz[k]);
          fi += f;
          ti += Vec3(b.tix[k], b.tiy[k], b.tiz[k]);
          const std::size_t j = b.j[k];
          if (j >= begin && j < end) {
            force[j] -= f;
            torque[j] += tj;
          } else {
            queue.push_back({b.j[k], -f, tj});
          }
          const double smaller = std::min(rad[b.i[k]], rad[j]);
          if (b.overlap[k] > worst.ratio * smaller) worst = {b.overlap[k] / smaller, b.i[k], false};
        }
        b.count = 0;
      };
      b.count = 0;
      for (std::size_t i = begin; i < end; ++i) {
        const Vec3 xi = x[i];
        const double ri = rad[i];
        for (std::uint32_t e = first[i]; e < first[i + 1]; ++e) {
          const std::size_t j = partner[e];
          const Vec3 d = box.minimum_image(xi - x[j]);
          const double rj = rad[j];
          const double reach = ri + rj;
          const double r2 = squared_norm(d);  // contact_kinematics.hpp
          if (r2 >= reach * reach) {
            clear_history<Law>(history + static_cast<std::size_t>(e) * kHistory);
            continue;
          }
          const std::size_t k = b.count;
          b.i[k] = static_cast<std::uint32_t>(i);
          b.j[k] = static_cast<std::uint32_t>(j);
          b.entry[k] = e;
          b.set_pair(k, d, r2, ri, rj, v[i] - v[j], w[i], w[j]);
          if (uniform.yes) {
            b.radius[k] = uniform.radius;
            b.mass[k] = uniform.mass;
            b.inertia[k] = uniform.inertia;
          } else {
            b.radius[k] = ri * rj / reach;
            b.mass[k] = mass[i] * mass[j] / (mass[i] + mass[j]);
            b.inertia[k] = inertia[i] * inertia[j] / (inertia[i] + inertia[j]);
          }
          const double* h = history + static_cast<std::size_t>(e) * kHistory;
          for (std::size_t q = 0; q < kHistory; ++q) b.history[q][k] = h[q];
          if (++b.count == Batch::kSize) run_batch();
        }
      }
      run_batch();
      if (begin < end) {
        force[row] += fi;
        torque[row] += ti;
      }
      own_[tid].worst = worst;
#pragma omp barrier
      for (std::size_t t = 0; t < nt; ++t)
        for (const Reaction& q : own_[t].queue)
          if (q.slot >= begin && q.slot < end) {
            force[q.slot] += q.force;
            torque[q.slot] += q.torque;
          }
      if (walls) {
        const auto start = std::chrono::steady_clock::now();
        own_[tid].wall_worst = walls_.rows(c, std::min(begin, c.owned), std::min(end, c.owned),
                                           own_[tid].wall_scratch);
        if (tid == 0)
          wall_seconds =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
    }
    DeepestOverlap result;
    for (const auto& o : own_)
      if (o.worst.ratio > result.ratio) result = o.worst;
    if (walls)
      for (const auto& o : own_)
        if (o.wall_worst.ratio > walls->ratio ||
            (o.wall_worst.ratio == walls->ratio && o.wall_worst.slot < walls->slot))
          *walls = o.wall_worst;
    return result;
  }

 private:
  using Batch = ContactBatch<kHistory>;
  struct UniformBodies {
    bool yes = false;
    double radius = 0.0, mass = 0.0, inertia = 0.0;  // R*, m*, I* of every pair
  };
  // Whether all particles share radius, mass and inertia, and then the pair constants. Looked
  // at again only after a rebuild (insertion, removal and re-sorting all rebuild the list).
  UniformBodies uniform_bodies(const ParticleStore& p, std::size_t rebuild) {
    if (uniform_rebuild_ == rebuild && uniform_count_ == p.size()) return uniform_;
    uniform_rebuild_ = rebuild;
    uniform_count_ = p.size();
    uniform_ = {};
    if (p.size() == 0) return uniform_;
    const double r = p.radius[0], m = p.mass[0], in = p.inertia[0];
    for (std::size_t k = 1; k < p.size(); ++k)
      if (p.radius[k] != r || p.mass[k] != m || p.inertia[k] != in) return uniform_;
    const double reach = r + r;
    uniform_ = {true, r * r / reach, m * m / (m + m), in * in / (in + in)};
    return uniform_;
  }

  Law particle_particle_;
  WallContactForces<Law> walls_;
  struct Reaction {
    std::uint32_t slot;  // the body of another thread's block
    Vec3 force;
    Vec3 torque;
  };
  // What one thread of the pair loop owns, on cache lines of its own (the queue's size is
  // written at every push; two threads' queues on one line would bounce it between cores).
  struct alignas(64) ThreadShare {
    Batch batch;
    typename WallContactForces<Law>::Scratch wall_scratch;
    std::vector<Reaction> queue;
    DeepestOverlap worst;
    DeepestOverlap wall_worst;
  };
  std::vector<ThreadShare> own_;
  UniformBodies uniform_;
  std::size_t uniform_rebuild_ = static_cast<std::size_t>(-1);
  std::size_t uniform_count_ = 0;
};

// The LawForces of `choice` with NormalParts' part I as its normal part (force_kernel.hpp).
template <std::size_t I>
std::unique_ptr<ForceKernel> make_force_kernel_of_normal(const ContactLawChoice& choice,
                                                         const DemParameters& dem) {
  using Normal = NormalParts::At<I>;
  return with_contact_law_of_normal<Normal>(choice, [&](auto tag) -> std::unique_ptr<ForceKernel> {
    using Law = typename decltype(tag)::type;
    return std::make_unique<LawForces<Law>>(dem);
  });
}

}  // namespace feedflow
