#include "fullsim/dem/scene/rain_fill.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "fullsim/common/progress_line.hpp"
#include "models/core/errors.hpp"
#include "models/core/printf_format.hpp"
#include "models/os/interrupt_request.hpp"

namespace feedflow {
namespace {

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
// and are removed anyway), of every rank's.
double kept_max_speed(const BedView& bed, const std::optional<double>& trim_height) {
  const ParticleStore& p = bed.store();
  double v2 = 0.0;
  for (std::size_t k = 0; k < bed.own(); ++k)
    if (!trim_height || p.position[k].z() <= *trim_height) v2 = std::max(v2, p.velocity[k].squaredNorm());
  return std::sqrt(bed.max(v2));
}

}  // namespace

double resting_fill_top(const BedView& bed, double resting_speed) {
  const ParticleStore& p = bed.store();
  double top = -std::numeric_limits<double>::infinity();
  const double v2 = resting_speed * resting_speed;
  for (std::size_t k = 0; k < bed.own(); ++k)
    if (p.velocity[k].squaredNorm() < v2) top = std::max(top, p.position[k].z());
  return bed.max(top);
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

RainFill::RainFill(RainFillSettings settings) : settings_(std::move(settings)) {
  check(settings_);
  sphere_mass_ = settings_.density * 4.0 / 3.0 * std::numbers::pi * std::pow(settings_.radius, 3);
}

// Runs the whole steps that cover `duration` (or the rest of the advance under way), in chunks,
// so Ctrl-C is seen within a few hundred steps; false when it was.
bool RainFill::advance(DemEngine& engine, double duration) {
  constexpr long kChunk = 200;
  if (!goal_) goal_ = engine.time() + engine.whole_steps(duration, StepRounding::up);
  while (!engine.reached(*goal_)) {
    if (engine.raised_on_any(interrupt_requested()) && engine.checkpoint_ready()) return false;
    engine.advance_to(*goal_, kChunk);
  }
  goal_.reset();
  return true;
}

// Places what is due by the end of the current batch interval (or the rest of the batch under
// way, with the region where it began), then inserts the batch into the engine: until then the
// engine is untouched, so Ctrl-C inside a batch leaves a state that can be checkpointed.
bool RainFill::insert_batch(DemEngine& engine) {
  const RainFillSettings& s = settings_;
  const Vec3 extent = s.region_upper - s.region_lower;
  const double due_mass = s.mass_rate * (engine.time() - t0_ + s.batch_interval);
  if (!batch_lower_z_) {
    batch_lower_z_ = s.region_lower.z();
    if (s.follow_gap > 0.0) {
      const double top = resting_fill_top(engine.bed(), s.resting_speed);
      if (std::isfinite(top)) batch_lower_z_ = std::max(*batch_lower_z_, top + s.follow_gap);
    }
  }
  Vec3 lower = s.region_lower;
  lower.z() = *batch_lower_z_;
  // Particles that can touch a sphere placed in the region, of every rank (so on a run shared
  // among ranks every rank places the same spheres).
  const BedView bed = engine.bed();
  const double reach = s.radius + bed.max(bed.store().max_radius());
  const ParticleStore p = bed.gathered([&](std::size_t k) {
    const double z = bed.store().position[k].z();
    return z > lower.z() - reach && z < lower.z() + extent.z() + reach;
  });
  std::vector<std::size_t> near(p.size());
  for (std::size_t k = 0; k < near.size(); ++k) near[k] = k;
  auto touches_placed = [&](const Vec3& x) {
    for (const Vec3& y : placed_)
      if (engine.box().minimum_image(x - y).squaredNorm() < 4.0 * s.radius * s.radius) return true;
    return false;
  };
  FillReport& report = report_;
  const double mass = ParticleStore::sphere_mass(s.density, s.radius);  // as the store books it
  while (report.inserted_mass + sphere_mass_ <= due_mass * (1.0 + 1e-12) &&
         report.inserted_mass + 0.5 * sphere_mass_ < s.target_mass &&
         report.inserted_count < s.target_count) {
    // An atomic load, cheap beside the placement (shared among ranks, a sum over them).
    if (engine.raised_on_any(interrupt_requested())) return false;
    bool placed = false;
    for (int a = 0; a < s.attempts && !placed; ++a) {
      Vec3 x;
      for (int d = 0; d < 3; ++d) x[d] = lower[d] + extent[d] * uniform(rng_);
      x = engine.box().wrap(x);
      if (s.admits && !s.admits(x, s.radius)) continue;
      if (touches_particle(p, engine.box(), near, x, s.radius) || touches_placed(x)) continue;
      if (touches_wall(engine, x, s.radius)) continue;
      placed_.push_back(x);
      report.inserted_mass += mass;
      ++report.inserted_count;
      placed = true;
    }
    if (!placed) {
      ++report.failed_placements;
      break;  // the region is crowded: the rest waits for the next batch
    }
  }
  for (const Vec3& x : placed_) engine.insert_particle(x, s.radius, s.density, 0.0, s.initial_velocity);
  placed_.clear();
  batch_lower_z_.reset();
  return true;
}

bool RainFill::target_reached(const DemEngine& engine) const {
  const RainFillSettings& s = settings_;
  return report_.inserted_mass + 0.5 * sphere_mass_ >= s.target_mass ||
         report_.inserted_count >= s.target_count ||
         (s.target_height && resting_fill_top(engine.bed(), s.resting_speed) >= *s.target_height);
}

FillReport RainFill::run(DemEngine& engine, std::ostream& log) {
  const RainFillSettings& s = settings_;
  FillReport& report = report_;
  report.interrupted = false;
  auto interrupted = [&] {
    report.interrupted = true;
    return report;
  };
  if (phase_ == Phase::done) return report;
  if (phase_ == Phase::start) {
    rng_.seed(s.seed);
    const DemEngine::SunkTally sunk = engine.sunk();
    sunk_before_ = sunk.mass;
    sunk_count_before_ = static_cast<std::size_t>(sunk.count);
    t0_ = engine.time();
    if (!insert_batch(engine)) return interrupted();
    phase_ = Phase::inserting;
  } else {
    log << format("  fill: continued at t = %.4g s (%zu spheres, %.6g kg in)\n", engine.time(),
                  report.inserted_count, report.inserted_mass);
  }
  engine.prepare(log);

  if (phase_ == Phase::inserting) {
    const double goal =
        std::isfinite(s.target_mass)
            ? s.target_mass
            : static_cast<double>(std::min<std::size_t>(s.target_count, 1u << 30)) * sphere_mass_;
    if (next_note_ == 0.0) next_note_ = 0.1 * goal;
    SilentProgress silent;
    ProgressSink& progress = s.progress ? *s.progress : silent;
    progress.begin("DEM fill", goal, "kg");
    struct FinishOnReturn {
      ProgressSink& sink;
      ~FinishOnReturn() { sink.finish(); }
    } finish_progress{progress};
    progress.update(report.inserted_mass);
    const auto wall_start = ProgressLine::Clock::now();
    const double mass_at_start = report.inserted_mass;
    // A batch under way (stopped inside insert_batch) is finished before the next advance.
    while (batch_lower_z_ || (!target_reached(engine) && engine.time() - t0_ < s.insert_time_cap)) {
      if (!batch_lower_z_ && !advance(engine, s.batch_interval)) return interrupted();
      if (!insert_batch(engine)) return interrupted();
      progress.update(report.inserted_mass);
      if (report.inserted_mass >= next_note_) {  // a line per tenth for logs that are not terminals
        const double elapsed =
            std::chrono::duration<double>(ProgressLine::Clock::now() - wall_start).count();
        const double eta = ProgressLine::eta_seconds(
            elapsed, (report.inserted_mass - mass_at_start) / std::max(goal - mass_at_start, 1e-300));
        log << format("  fill: %.4g of %.4g kg in at t = %.4g s (%zu spheres), %.0f s wall, "
                      "ETA of the insertion %.0f s\n",
                      report.inserted_mass, goal, engine.time(), engine.global_count(), elapsed,
                      std::max(0.0, eta));
        next_note_ += 0.1 * goal;
      }
    }
    progress.finish();
    report.target_reached = target_reached(engine);
    report.insert_end_time = engine.time();
    log << format("  fill: inserting done at t = %.4g s (%zu spheres, %.6g kg)\n", engine.time(),
                  report.inserted_count, report.inserted_mass);
    phase_ = Phase::settling;
    settle_start_ = engine.time();
    settle_checks_ = 0;
  }

  // Settling: at least one check interval, so freshly inserted spheres have landed.
  do {
    if (!advance(engine, s.settle_check_interval)) return interrupted();
    report.final_max_speed = kept_max_speed(engine.bed(), s.trim_height);
    report.settled = report.final_max_speed < s.settle_speed;
    if (++settle_checks_ % 20 == 0)  // a line per 0.1 s of settling (default check interval)
      log << format("  fill: settling at t = %.4g s, largest kept speed %.3g mm/s (goal %.3g)\n",
                    engine.time(), report.final_max_speed * 1e3, s.settle_speed * 1e3);
  } while (!report.settled && engine.time() - settle_start_ < s.settle_time_cap);
  finish(engine, log);
  phase_ = Phase::done;
  return report;
}

void RainFill::finish(DemEngine& engine, std::ostream& log) {
  const RainFillSettings& s = settings_;
  FillReport& report = report_;
  if (s.trim_height) {
    // Each rank removes its own (a ghost's flag is ignored); the books are summed over them.
    const BedView bed = engine.bed();
    std::vector<double> trimmed{0.0, 0.0};  // count, mass
    for (std::size_t k = 0; k < bed.own(); ++k)
      if (bed.store().position[k].z() > *s.trim_height) {
        trimmed[0] += 1.0;
        trimmed[1] += bed.store().mass[k];
      }
    bed.sum(trimmed);
    report.trimmed_count += static_cast<std::size_t>(trimmed[0]);
    report.trimmed_mass += trimmed[1];
    const ParticleStore& mine = engine.particles();
    std::vector<char> above(mine.size(), 0);
    for (std::size_t k = 0; k < mine.size(); ++k) above[k] = mine.position[k].z() > *s.trim_height;
    if (report.trimmed_count > 0) engine.remove_particles(above);
  }
  ParticleStore& p = engine.particles();
  for (std::size_t k = 0; k < p.size(); ++k)
    p.layer[k] = std::isfinite(s.band_height)
                     ? std::floor((p.position[k].z() - s.band_origin) / s.band_height)
                     : 0.0;
  const DemEngine::SunkTally sunk = engine.sunk();
  report.sunk_mass = sunk.mass - sunk_before_;
  report.sunk_count = static_cast<std::size_t>(sunk.count) - sunk_count_before_;
  report.end_time = engine.time();
  log << report.describe();
}

namespace {

// Optional numbers are saved as NaN when unset.
double or_nan(const std::optional<double>& v) { return v.value_or(std::numeric_limits<double>::quiet_NaN()); }
std::optional<double> unless_nan(double v) { return std::isnan(v) ? std::nullopt : std::optional<double>(v); }

constexpr const char* kGroup = "/fill";

}  // namespace

bool RainFill::saved_in(const Hdf5File& f) { return f.exists(kGroup); }

bool RainFill::save(const DemEngine& engine, Hdf5File& f) const {
  if (!report_.interrupted || phase_ == Phase::start) return false;
  engine.write_checkpoint(f);
  const std::string g = kGroup;
  f.create_group(g);
  std::ostringstream rng;
  rng << rng_;
  f.set_attribute(g, "phase", static_cast<std::int64_t>(phase_));
  f.set_attribute(g, "random_stream", rng.str());
  f.set_attribute(g, "start_time", t0_);
  f.set_attribute(g, "sunk_mass_before", sunk_before_);
  f.set_attribute(g, "sunk_count_before", static_cast<std::int64_t>(sunk_count_before_));
  f.set_attribute(g, "inserted_count", static_cast<std::int64_t>(report_.inserted_count));
  f.set_attribute(g, "inserted_mass", report_.inserted_mass);
  f.set_attribute(g, "failed_placements", static_cast<std::int64_t>(report_.failed_placements));
  f.set_attribute(g, "insert_end_time", report_.insert_end_time);
  f.set_attribute(g, "target_reached", static_cast<std::int64_t>(report_.target_reached));
  f.set_attribute(g, "advance_goal", or_nan(goal_));
  f.set_attribute(g, "batch_region_bottom", or_nan(batch_lower_z_));
  std::vector<double> placed;
  for (const Vec3& x : placed_) placed.insert(placed.end(), {x.x(), x.y(), x.z()});
  f.write(g + "/placed", placed, {placed_.size(), 3}, "m");
  f.set_attribute(g, "next_note", next_note_);
  f.set_attribute(g, "settle_start", settle_start_);
  f.set_attribute(g, "settle_checks", static_cast<std::int64_t>(settle_checks_));
  return true;
}

void RainFill::restore(DemEngine& engine, const Hdf5File& f) {
  const std::string g = kGroup;
  if (!f.exists(g)) throw std::runtime_error(f.path().string() + " holds no fill under way (" + g + ")");
  const std::int64_t phase = f.integer_attribute(g, "phase");
  if (phase != static_cast<std::int64_t>(Phase::inserting) && phase != static_cast<std::int64_t>(Phase::settling))
    throw std::runtime_error(f.path().string() + ": " + g + " holds no fill under way (phase " +
                             std::to_string(phase) + ")");
  phase_ = static_cast<Phase>(phase);
  std::istringstream rng(f.string_attribute(g, "random_stream"));
  rng >> rng_;
  if (!rng) throw std::runtime_error(f.path().string() + ": " + g + " has a damaged random stream");
  t0_ = f.double_attribute(g, "start_time");
  sunk_before_ = f.double_attribute(g, "sunk_mass_before");
  sunk_count_before_ = static_cast<std::size_t>(f.integer_attribute(g, "sunk_count_before"));
  report_ = FillReport{};
  report_.inserted_count = static_cast<std::size_t>(f.integer_attribute(g, "inserted_count"));
  report_.inserted_mass = f.double_attribute(g, "inserted_mass");
  report_.failed_placements = static_cast<std::size_t>(f.integer_attribute(g, "failed_placements"));
  report_.insert_end_time = f.double_attribute(g, "insert_end_time");
  report_.target_reached = f.integer_attribute(g, "target_reached") != 0;
  goal_ = unless_nan(f.double_attribute(g, "advance_goal"));
  batch_lower_z_ = unless_nan(f.double_attribute(g, "batch_region_bottom"));
  const std::size_t placed = f.dims(g + "/placed").at(0);
  const std::vector<double> xyz = f.read<double>(g + "/placed", {placed, 3});
  placed_.clear();
  for (std::size_t k = 0; k < placed; ++k) placed_.emplace_back(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
  next_note_ = f.double_attribute(g, "next_note");
  settle_start_ = f.double_attribute(g, "settle_start");
  settle_checks_ = static_cast<long>(f.integer_attribute(g, "settle_checks"));
  engine.restore(f);
}

FillReport rain_fill(DemEngine& engine, const RainFillSettings& settings, std::ostream& log) {
  return RainFill(settings).run(engine, log);
}

}  // namespace feedflow
