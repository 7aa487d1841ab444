#include "fullsim/dem/scene/rain_fill.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "fullsim/common/progress_line.hpp"
#include "models/core/errors.hpp"
#include "models/os/interrupt_request.hpp"

namespace feedflow {
namespace {

std::string format(const char* fmt, auto... args) {
  char buf[400];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

// Uniform in [0, 1) from the top 53 bits: the same numbers on every platform.
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

bool touches_wall(const DemEngine& engine, const Vec3& x, double r) {
  const double t = engine.time();
  for (const auto& w : engine.walls())
    if (w.active(t) && w.touch(x).gap < r) return true;
  std::array<MeshTouch, MeshWall::kMaxContacts> touches;
  for (const auto& m : engine.mesh_walls())
    if (m.active(t) && m.touches(x, r, touches) > 0) return true;
  return false;
}

bool touches_particle(const ParticleStore& p, const SimulationBox& box,
                      const std::vector<std::size_t>& candidates, const Vec3& x, double r) {
  for (std::size_t k : candidates) {
    const double reach = r + p.radius[k];
    if (box.minimum_image(x - p.position[k]).squaredNorm() < reach * reach) return true;
  }
  return false;
}

void check(const RainFillSettings& s) {
  auto bad = [](const std::string& what) { throw InputError("", "dem.fill", what); };
  if (!(s.radius > 0.0) || !(s.density > 0.0)) bad("the inserted spheres need a radius and a density > 0");
  if (!(s.mass_rate > 0.0)) bad("the insertion mass rate must be > 0 kg/s");
  if (!(s.batch_interval > 0.0)) bad("the insertion batch interval must be > 0 s");
  if ((s.region_upper.array() < s.region_lower.array()).any())
    bad("the insertion region's upper corner lies below its lower corner");
  if (!std::isfinite(s.target_mass) && s.target_count == std::numeric_limits<std::size_t>::max() &&
      !s.target_height)
    bad("the fill needs a target mass, count or height");
  if (!(s.band_height > 0.0)) bad("the layer band height must be > 0 m");
}

// The largest speed among the particles the trim will keep (those above roll on the heap top
// and are removed anyway).
double kept_max_speed(const ParticleStore& p, const std::optional<double>& trim_height) {
  double v2 = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k)
    if (!trim_height || p.position[k].z() <= *trim_height) v2 = std::max(v2, p.velocity[k].squaredNorm());
  return std::sqrt(v2);
}

// Runs the whole steps that cover `duration`, in chunks, so Ctrl-C is seen within a few
// hundred steps; false when it was.
bool run_or_interrupted(DemEngine& engine, double duration) {
  constexpr long kChunk = 200;
  const double t = engine.time() + engine.whole_steps(duration, StepRounding::up);
  while (!engine.reached(t)) {
    if (interrupt_requested()) return false;
    engine.advance_to(t, kChunk);
  }
  return true;
}

}  // namespace

double resting_fill_top(const ParticleStore& p, double resting_speed) {
  double top = -std::numeric_limits<double>::infinity();
  const double v2 = resting_speed * resting_speed;
  for (std::size_t k = 0; k < p.size(); ++k)
    if (p.velocity[k].squaredNorm() < v2) top = std::max(top, p.position[k].z());
  return top;
}

bool overlaps_anything(const DemEngine& engine, const Vec3& x, double radius) {
  std::vector<std::size_t> all(engine.particles().size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  return touches_particle(engine.particles(), engine.box(), all, x, radius) ||
         touches_wall(engine, x, radius);
}

std::string RainFillSettings::describe() const {
  std::string s = format("rain-fall at %.3g kg/s from a %.3g mm tall region", mass_rate,
                         (region_upper.z() - region_lower.z()) * 1e3);
  if (follow_gap > 0.0) s += format(" riding %.3g mm above the resting fill", follow_gap * 1e3);
  s += format(", spheres starting at %.3g m/s", initial_velocity.norm());
  if (std::isfinite(target_mass)) s += format(", to %.4g kg", target_mass);
  if (target_count != std::numeric_limits<std::size_t>::max()) s += format(", to %zu spheres", target_count);
  s += format(", settled below %.3g mm/s (at most %.3g s)", settle_speed * 1e3, settle_time_cap);
  // (a fill line at the drum's axis comes out as -4e-15 m from the cosine: printed as 0)
  if (trim_height)
    s += format(", centres above z = %.4g mm removed",
                std::abs(*trim_height) < 1e-9 ? 0.0 : *trim_height * 1e3);
  return s;
}

std::string FillReport::describe() const {
  std::string s = format("  fill: %zu spheres (%.6g kg) rained in by t = %.4g s%s; ",
                         inserted_count, inserted_mass, insert_end_time,
                         target_reached ? "" : " (time cap: target NOT reached)");
  s += settled ? format("settled (largest speed %.3g mm/s) at t = %.4g s",
                        final_max_speed * 1e3, end_time)
               : format("settling stopped by its time cap at t = %.4g s (largest speed %.3g mm/s)",
                        end_time, final_max_speed * 1e3);
  s += format("; %zu trimmed (%.6g kg)", trimmed_count, trimmed_mass);
  if (sunk_count > 0) s += format("; %zu taken by the sink while filling (%.6g kg)", sunk_count, sunk_mass);
  if (failed_placements > 0) s += format("; %zu placements retried", failed_placements);
  return s + "\n";
}

std::string FillReport::summary() const {
  return format("%zu spheres rained in, %zu trimmed", inserted_count, trimmed_count) +
         (settled ? format(", settled (largest speed %.3g mm/s)", final_max_speed * 1e3)
                  : format(", NOT settled below the threshold within the time cap (largest speed "
                           "%.3g mm/s)", final_max_speed * 1e3));
}

FillReport rain_fill(DemEngine& engine, const RainFillSettings& s, std::ostream& log) {
  check(s);
  FillReport report;
  std::mt19937_64 rng(s.seed);
  const double sphere_mass = s.density * 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius, 3);
  const double sunk_before = engine.outlet_sink() ? engine.outlet_sink()->removed_mass() : 0.0;
  const std::size_t sunk_count_before = engine.outlet_sink() ? engine.outlet_sink()->removed_count() : 0;
  const double t0 = engine.time();
  const Vec3 extent = s.region_upper - s.region_lower;

  // Inserts what is due by the end of the current batch interval.
  auto insert_batch = [&] {
    const double due_mass = s.mass_rate * (engine.time() - t0 + s.batch_interval);
    Vec3 lower = s.region_lower;
    if (s.follow_gap > 0.0) {
      const double top = resting_fill_top(engine.particles(), s.resting_speed);
      if (std::isfinite(top)) lower.z() = std::max(lower.z(), top + s.follow_gap);
    }
    // Particles that can touch a sphere placed in the region.
    const ParticleStore& p = engine.particles();
    std::vector<std::size_t> near;
    const double reach = s.radius + p.max_radius();
    for (std::size_t k = 0; k < p.size(); ++k) {
      const double z = p.position[k].z();
      if (z > lower.z() - reach && z < lower.z() + extent.z() + reach) near.push_back(k);
    }
    while (report.inserted_mass + sphere_mass <= due_mass * (1.0 + 1e-12) &&
           report.inserted_mass + 0.5 * sphere_mass < s.target_mass &&
           report.inserted_count < s.target_count) {
      if (report.inserted_count % 1024 == 0 && interrupt_requested()) {
        report.interrupted = true;
        return;
      }
      bool placed = false;
      for (int a = 0; a < s.attempts && !placed; ++a) {
        Vec3 x;
        for (int d = 0; d < 3; ++d) x[d] = lower[d] + extent[d] * uniform(rng);
        x = engine.box().wrap(x);
        if (s.admits && !s.admits(x, s.radius)) continue;
        if (touches_particle(engine.particles(), engine.box(), near, x, s.radius)) continue;
        if (touches_wall(engine, x, s.radius)) continue;
        engine.insert_particle(x, s.radius, s.density, 0.0, s.initial_velocity);
        near.push_back(engine.particles().size() - 1);
        report.inserted_mass += engine.particles().mass.back();  // the very number the store holds
        ++report.inserted_count;
        placed = true;
      }
      if (!placed) {
        ++report.failed_placements;
        break;  // the region is crowded: the rest waits for the next batch
      }
    }
  };
  auto target_reached = [&] {
    return report.inserted_mass + 0.5 * sphere_mass >= s.target_mass ||
           report.inserted_count >= s.target_count ||
           (s.target_height &&
            resting_fill_top(engine.particles(), s.resting_speed) >= *s.target_height);
  };

  insert_batch();
  if (report.interrupted) return report;
  engine.prepare(log);
  const double goal = std::isfinite(s.target_mass)
                          ? s.target_mass
                          : static_cast<double>(std::min<std::size_t>(s.target_count, 1u << 30)) * sphere_mass;
  SilentProgress silent;
  ProgressSink& progress = s.progress ? *s.progress : silent;
  progress.begin("DEM fill", goal, "kg");
  struct FinishOnReturn {
    ProgressSink& sink;
    ~FinishOnReturn() { sink.finish(); }
  } finish_progress{progress};
  double next_note = 0.1 * goal;
  const auto wall_start = ProgressLine::Clock::now();
  while (!target_reached() && engine.time() - t0 < s.insert_time_cap) {
    if (!run_or_interrupted(engine, s.batch_interval)) {
      report.interrupted = true;
      return report;
    }
    insert_batch();
    if (report.interrupted) return report;
    progress.update(report.inserted_mass);
    if (report.inserted_mass >= next_note) {  // a line per tenth for logs that are not terminals
      const double elapsed =
          std::chrono::duration<double>(ProgressLine::Clock::now() - wall_start).count();
      const double eta = ProgressLine::eta_seconds(elapsed, report.inserted_mass / goal);
      log << format("  fill: %.4g of %.4g kg in at t = %.4g s (%zu spheres), %.0f s wall, "
                    "ETA of the insertion %.0f s\n",
                    report.inserted_mass, goal, engine.time(), engine.particles().size(), elapsed,
                    std::max(0.0, eta));
      next_note += 0.1 * goal;
    }
  }
  progress.finish();
  report.target_reached = target_reached();
  report.insert_end_time = engine.time();
  log << format("  fill: inserting done at t = %.4g s (%zu spheres, %.6g kg)\n", engine.time(),
                report.inserted_count, report.inserted_mass);

  // Settling: at least one check interval, so freshly inserted spheres have landed.
  const double settle_start = engine.time();
  long settle_checks = 0;
  do {
    if (!run_or_interrupted(engine, s.settle_check_interval)) {
      report.interrupted = true;
      return report;
    }
    report.final_max_speed = kept_max_speed(engine.particles(), s.trim_height);
    report.settled = report.final_max_speed < s.settle_speed;
    if (++settle_checks % 20 == 0)  // a line per 0.1 s of settling (default check interval)
      log << format("  fill: settling at t = %.4g s, largest kept speed %.3g mm/s (goal %.3g)\n",
                    engine.time(), report.final_max_speed * 1e3, s.settle_speed * 1e3);
  } while (!report.settled && engine.time() - settle_start < s.settle_time_cap);

  ParticleStore& p = engine.particles();
  if (s.trim_height) {
    std::vector<char> above(p.size(), 0);
    for (std::size_t k = 0; k < p.size(); ++k)
      if (p.position[k].z() > *s.trim_height) {
        above[k] = 1;
        ++report.trimmed_count;
        report.trimmed_mass += p.mass[k];
      }
    if (report.trimmed_count > 0) engine.remove_particles(above);
  }
  for (std::size_t k = 0; k < p.size(); ++k)
    p.layer[k] = std::isfinite(s.band_height)
                     ? std::floor((p.position[k].z() - s.band_origin) / s.band_height)
                     : 0.0;
  if (const OutletSink* sink = engine.outlet_sink()) {
    report.sunk_mass = sink->removed_mass() - sunk_before;
    report.sunk_count = sink->removed_count() - sunk_count_before;
  }
  report.end_time = engine.time();
  log << report.describe();
  return report;
}

}  // namespace feedflow
