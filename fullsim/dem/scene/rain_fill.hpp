#pragma once
// Rain-fall filling of a DEM scene (seed 3.1.1, data.md 2.2), scene-independent: spheres are
// dropped at random positions of an insertion region (an axis-aligned box of centres; an axis
// with lower == upper is held at that coordinate, e.g. the mid-plane of a one-layer slab;
// periodic axes of the box are respected) at a mass rate, each placed only where it overlaps no
// particle and no active wall (and where the scene's `admits` says it is inside the
// container), with an initial velocity. Insertion stops at the target mass, count or
// resting fill height; the fill
// then settles until the largest speed (of the particles below the trim height, which stay) is
// below a threshold (seed: 1 mm/s) or a time cap;
// particles whose centre lies above the trim height are removed; each particle's `layer` is
// set to the band of its settled height (floor((z - band_origin) / band_height)), for the
// flow-pattern measurement. Deterministic for a seed (own 53-bit uniform draws, no
// implementation-defined distributions).
//
// The region can follow the fill (follow_gap > 0): its bottom is kept `follow_gap` above the
// highest resting particle, so the drop height stays small. Soft particles (E = 1 MPa) falling
// the seed's 1.2 m would hit at ~5 m/s and overlap by ~0.4 R, beyond the blow-up guard.
//
//   RainFillSettings fill;  fill.region_lower = ...; fill.mass_rate = 0.2; ...
//   DemEngine engine(settings, box, ParticleStore{});   // walls, sink, then:
//   FillReport r = rain_fill(engine, fill, std::cout);  // prepares the engine itself
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/common/progress_sink.hpp"
#include "fullsim/dem/dem_engine.hpp"

namespace feedflow {

// What the scenes' rain fills share: the rain's initial speed (with a drop of ~10 R it lands at
// ~0.7 m/s, soft enough for the hysteretic law), the solid fraction of a poured bed of spheres
// (the fill mass and the rate assume it), the rate of bed rise the insertion region feeds
// without crowding, and the surplus rained so the trim leaves a level top.
inline constexpr double kRainSpeed = 0.5;      // [m/s]
inline constexpr double kPouredPacking = 0.6;  // solid fraction
inline constexpr double kRainRiseSpeed = 0.1;  // [m/s] of bed height
inline constexpr double kRainSurplus = 1.2;    // rained mass / fill mass

struct RainFillSettings {
  Vec3 region_lower = Vec3::Zero();  // insertion region of the centres [m]
  Vec3 region_upper = Vec3::Zero();
  double follow_gap = 0.0;           // [m] > 0: the region rides this far above the resting fill
  double resting_speed = 0.2;        // [m/s] particles slower than this make up the fill
  double radius = 0.0;               // [m]
  double density = 0.0;              // [kg/m^3]
  double mass_rate = 0.0;            // [kg/s] inserted
  double target_mass = std::numeric_limits<double>::infinity();  // [kg] stop inserting here
  std::size_t target_count = std::numeric_limits<std::size_t>::max();
  // [m] also stop once the resting fill's top centre reaches this height (none: mass/count only)
  std::optional<double> target_height;
  Vec3 initial_velocity = Vec3::Zero();  // [m/s] (downward for rain)
  double batch_interval = 0.01;      // [s] between insertion batches
  int attempts = 60;                 // random tries per particle before it waits for the next batch
  double insert_time_cap = 10.0;     // [s] of inserting before giving up (region too small)
  double settle_speed = 1e-3;        // [m/s] settled when the largest speed is below
  double settle_time_cap = 2.0;      // [s] of settling at most
  double settle_check_interval = 0.005;  // [s] between speed checks
  std::optional<double> trim_height; // [m] centres above are removed after settling
  double band_origin = 0.0;          // [m] height of the lowest band's bottom
  double band_height = std::numeric_limits<double>::infinity();  // [m]; inf: one band (0)
  std::uint64_t seed = 1;
  ProgressSink* progress = nullptr;  // the inserted mass against the target (none: silent)
  // Whether a centre may receive a sphere (inside the container); none: everywhere.
  std::function<bool(const Vec3& centre, double radius)> admits;

  // One plan line: "rain-fall at X kg/s from a region ..., to Y kg, settled below ..., trimmed
  // above ..." (what a scene's plan says about its fill before it runs).
  std::string describe() const;
};

struct FillReport {
  std::size_t inserted_count = 0;
  double inserted_mass = 0.0;        // [kg]
  std::size_t trimmed_count = 0;
  double trimmed_mass = 0.0;         // [kg]
  std::size_t sunk_count = 0;        // taken by an outlet sink during the fill
  double sunk_mass = 0.0;            // [kg]
  double insert_end_time = 0.0;      // [s] engine time when the target was reached
  double end_time = 0.0;             // [s] after settling and trimming
  bool target_reached = false;
  bool settled = false;              // largest speed below settle_speed (else the cap ended it)
  double final_max_speed = 0.0;      // [m/s]
  std::size_t failed_placements = 0; // tries that found no free spot (retried later)
  bool interrupted = false;          // Ctrl-C while filling (RainFill::save: what can go on)
  std::string describe() const;      // the plan/log lines of the fill
  // "N spheres rained in, M trimmed, settled (largest speed X mm/s)" for a run's assumptions.
  std::string summary() const;
};

// One fill of one engine, which Ctrl-C can stop and a later run continue with the same bits.
// run() fills `engine` (prepared here if it is not yet; it needs no particles beforehand),
// settles, trims and tags the layers, writing one line per phase to `log`; it throws
// InputError for inconsistent settings (no rate, empty region). Ctrl-C (interrupt_request.hpp)
// is seen between insertions and steps: the report says `interrupted`, and once the first
// batch is in, save() writes the engine's checkpoint with the fill's state beside it, from
// which another process continues:
//
//   RainFill fill(settings);
//   if (fill.run(engine, log).interrupted) fill.save(engine, file);  // false: nothing to save
//   ... later, an engine of the same structure:
//   RainFill again(settings);  again.restore(engine, file);  again.run(engine, log);
//   // the same particles, bit for bit, as one uninterrupted fill
class RainFill {
 public:
  explicit RainFill(RainFillSettings settings);
  FillReport run(DemEngine& engine, std::ostream& log);
  // Where the inserted mass against the target goes (none: silent).
  void set_progress(ProgressSink* progress) { settings_.progress = progress; }
  // Stopped by Ctrl-C after its first batch: the engine's checkpoint and the fill's state
  // (phase, random stream, counts, the advance and the batch under way) into `file`; false
  // (nothing written) when there is nothing to continue.
  bool save(const DemEngine& engine, Hdf5File& file) const;
  // The engine's state and the fill's from a file save() wrote. Throws std::runtime_error
  // naming the file when it holds no fill under way.
  void restore(DemEngine& engine, const Hdf5File& file);
  // Whether `file` holds a fill under way (a checkpoint written by save()).
  static bool saved_in(const Hdf5File& file);
  const RainFillSettings& settings() const { return settings_; }

 private:
  enum class Phase : std::int64_t { start, inserting, settling, done };
  bool insert_batch(DemEngine& engine);  // false: interrupted
  bool target_reached(const DemEngine& engine) const;
  bool advance(DemEngine& engine, double duration);  // false: interrupted
  void finish(DemEngine& engine, std::ostream& log);  // trim, bands, the sink's share

  RainFillSettings settings_;
  double sphere_mass_ = 0.0;
  Phase phase_ = Phase::start;
  std::mt19937_64 rng_;
  double t0_ = 0.0;
  double sunk_before_ = 0.0;
  std::size_t sunk_count_before_ = 0;
  FillReport report_;
  std::optional<double> goal_;           // [s] the advance under way
  std::optional<double> batch_lower_z_;  // [m] the region's bottom of the batch under way
  std::vector<Vec3> placed_;             // [m] the batch under way's spheres, not yet inserted
  double next_note_ = 0.0;               // [kg] the next log line of the insertion
  double settle_start_ = 0.0;            // [s]
  long settle_checks_ = 0;
};

// A whole fill in one go: RainFill(settings).run(engine, log).
FillReport rain_fill(DemEngine& engine, const RainFillSettings& settings, std::ostream& log);

// The surface the region follows: the highest centre among particles slower than
// `resting_speed`; -infinity when none rests. Of every rank's particles (collective).
double resting_fill_top(const BedView& bed, double resting_speed);

}  // namespace feedflow
