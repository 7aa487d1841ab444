// What a DEM engine tells about itself: the plan it prints when prepared and the performance
// block of its run (with the balance over the ranks of a shared run).
#include <array>
#include <cstdio>
#include <sstream>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "fullsim/dem/dem_engine.hpp"
#include "models/core/printf_format.hpp"

namespace feedflow {
namespace {

int thread_count() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

}  // namespace

std::string DemEngine::make_plan() const {
  std::ostringstream s;
  s << "DEM plan\n";
  double own_mass = 0.0;
  for (std::size_t k = 0; k < owned_count(); ++k) own_mass += particles_.mass[k];
  s << format("  particles: %zu, largest radius %.4g m, total mass %.6g kg\n", global_count(),
              settings_.ranks.max(particles_.max_radius()), settings_.ranks.sum(own_mass));
  std::string axes;
  for (int a = 0; a < 3; ++a)
    if (box_.periodic[a]) axes += "xyz"[a];
  s << format("  box: (%.4g, %.4g, %.4g)-(%.4g, %.4g, %.4g) m, periodic axes: %s\n",
              box_.lower.x(), box_.lower.y(), box_.lower.z(), box_.upper.x(), box_.upper.y(),
              box_.upper.z(), axes.empty() ? "none" : axes.c_str());
  s << "  contact law (P-P and P-W, each with its Table 2 set): " << kernel_->name() << '\n';
  if (contact_law_name(effective_law_) != contact_law_name(settings_.law))
    s << "    (asked for: " << contact_law_name(settings_.law) << ")\n";
  for (const auto& k : skipped_) s << "  " << k << '\n';
  s << format("  history: %zu doubles per contact, beside its neighbour entry\n",
              kernel_->history_size());
  if (walls_.empty() && meshes_.empty()) s << "  walls: none\n";
  for (const auto& w : walls_) s << "  wall: " << w.describe() << '\n';
  for (const auto& m : meshes_) s << "  wall: " << m.describe() << '\n';
  s << "  " << (sink_ ? sink_->describe() : std::string("outlet sink: none")) << '\n';
  s << format("  gravity: (%.4g, %.4g, %.4g) m/s^2\n", settings_.gravity.x(),
              settings_.gravity.y(), settings_.gravity.z());
  if (holds_in_plane()) {
    const int axis = linear_free_.x() == 0.0 ? 0 : linear_free_.y() == 0.0 ? 1 : 2;
    s << format("  plane hold: every particle stays in the plane through its centre normal to %c "
                "(no force or velocity along %c, torque and spin about %c only)\n",
                "xyz"[axis], "xyz"[axis], "xyz"[axis]);
  }
  s << format("  time step: %.4g s, %s\n", time_step_.value, time_step_.justification.c_str());
  s << format("  neighbours: linked cells + half Verlet list, skin %.4g m (rebuild when a "
              "particle moves > skin/2), Morton re-sort every %zu rebuilds\n",
              neighbours_.skin(), settings_.sort_every);
  s << format("  OpenMP threads: %d (each owns a block of rows, cross-block reactions queued, "
              "no atomics)%s\n",
              thread_count(),
              particles_.size() >= settings_.parallel_from ? "" : "; this small system runs on one");
  s << "  " << guard_.describe() << '\n';
  s << format("  live step check: the springs of the deepest contact are re-taken whenever it "
              "passes %.3g R (then each 5 %% deeper); a warning above their stable step, a stop "
              "above period / pi\n",
              settings_.time_step.design_overlap);
  return s.str();
}

std::string DemEngine::performance_report() const { return performance().render(); }

std::string DemEngine::rank_balance() const {
  if (!shared()) return {};
  const DemRanks& ranks = settings_.ranks;
  auto spread = [&](double mine) {
    return std::array<double, 3>{-ranks.max(-mine), ranks.sum(mine) / ranks.size(), ranks.max(mine)};
  };
  std::string out = format("  per rank (min / mean / max over %d ranks):\n", ranks.size());
  const auto own = spread(static_cast<double>(owned_count()));
  out += format("    %-12s %10.0f %10.0f %10.0f\n", "particles", own[0], own[1], own[2]);
  const auto ghosts = spread(static_cast<double>(halo_.ghosts()));
  out += format("    %-12s %10.0f %10.0f %10.0f\n", "ghosts", ghosts[0], ghosts[1], ghosts[2]);
  // The same phases on every rank, in the order of this rank's report (every rank times the
  // same phases, as they run the same steps).
  for (const char* phase : {"pairs", "walls", "integration", "neighbours", "exchange"}) {
    const auto t = spread(report_.phase_seconds(phase));
    out += format("    %-12s %9.3f s %9.3f s %9.3f s\n", phase, t[0], t[1], t[2]);
  }
  return out;
}

void DemEngine::add_earlier_phases(const RunReport& earlier) {
  for (const auto& [phase, seconds] : earlier.phases()) report_.add_phase_time(phase, seconds);
}

RunReport DemEngine::performance() const {
  RunReport r = report_;
  r.set_wall_seconds(run_seconds_);
  // Over the steps this engine ran, in the time it spent on them (a continued run's earlier
  // steps were timed by the engine that ran them).
  const double rate =
      run_seconds_ > 0.0 ? (particle_steps_ - particle_steps_before_) / run_seconds_ : 0.0;
  r.add_figure("throughput", format("%.3g particle-steps/s", rate));
  r.add_figure("steps", format("%ld (dt %.4g s, t = %.4g s)", step_, time_step_.value, time_));
  r.add_figure("particles", format("%zu", global_count()));
  r.add_figure("neighbour pairs", format("%.2f per particle, %zu rebuilds",
                                         particles_.size() ? static_cast<double>(neighbours_.pair_count()) /
                                                                 static_cast<double>(particles_.size())
                                                           : 0.0,
                                         neighbours_.rebuild_count()));
  r.add_figure("threads", format("%d", thread_count()));
  if (shared()) {
    r.add_figure("ranks", format("%d (this one: %zu own particles, %zu ghosts from %zu "
                                 "neighbours; %zu re-cuts)",
                                 settings_.ranks.size(), halo_.owned(), halo_.ghosts(),
                                 halo_.neighbour_ranks().size(), rebalances_));
    // The balance: min / mean / max over the ranks (each rank times the same phases).
    const DemRanks& ranks = settings_.ranks;
    auto spread = [&](double mine, const char* unit) {
      return format("%.4g / %.4g / %.4g%s (min / mean / max over the ranks)", ranks.min(mine),
                    ranks.sum(mine) / ranks.size(), ranks.max(mine), unit);
    };
    r.add_figure("own particles", spread(static_cast<double>(halo_.owned()), ""));
    for (const char* phase : {"pairs", "walls", "neighbours", "exchange"})
      r.add_figure(std::string(phase) + " per rank", spread(report_.phase_seconds(phase), " s"));
    r.add_figure("sent per step", format("%.3g doubles (+ %.3g per step at rebuilds)",
                                         step_ > 0 ? halo_.step_doubles() / step_ : 0.0,
                                         step_ > 0 ? halo_.rebuild_doubles() / step_ : 0.0));
  }
  return r;
}

}  // namespace feedflow
