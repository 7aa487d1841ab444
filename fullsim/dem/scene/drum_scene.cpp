#include "fullsim/dem/scene/drum_scene.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "models/drum/drum_regime.hpp"
#include "models/units/angle.hpp"

namespace feedflow {

namespace {

// Rain-fall (rain_fill.hpp): the region's bottom rides kDrumFollowGap radii above the resting fill
// and is kDrumRegionHeight radii tall, so a sphere drops at most ~10 R (15 mm for the seed's
// spheres: ~0.7 m/s with the initial 0.5 m/s, soft enough for the hysteretic law); the rate
// raises the bed by kRainRiseSpeed, which the region can feed without crowding (a 0.01 s batch
// needs ~1 mm of bed, ~2 mm of the region's loose rain).
constexpr double kDrumFollowGap = 4.0;     // [R]
constexpr double kDrumRegionHeight = 6.0;  // [R]

SimulationBox drum_box(const DrumSceneSpec& s, double r) {
  const double R = 0.5 * s.diameter + 2.0 * r;
  const double depth = s.slab_depth ? *s.slab_depth : s.length;
  return SimulationBox{Vec3(-R, 0.0, -R), Vec3(R, depth, R), {false, s.slab_depth.has_value(), false}};
}

}  // namespace

DrumScene::DrumScene(DemSettings settings, DrumSceneSpec spec)
    : settings_(std::move(settings)), spec_(spec) {
  const double r = settings_.material.particle.radius;
  const double R = 0.5 * spec_.diameter;
  if (!(r > 0.0) || !(spec_.diameter > 8.0 * r))
    throw std::invalid_argument("drum scene: the drum must be wider than 8 particle radii");
  if (spec_.slab_depth && *spec_.slab_depth < 4.0 * r)
    throw std::invalid_argument("drum scene: the periodic slab must be at least two particle diameters deep");
  engine_ = std::make_unique<DemEngine>(settings_, drum_box(spec_, r), ParticleStore{});
  engine_->add_wall(Wall::cylinder("shell", Vec3::Zero(), Vec3::UnitY(), R, true));
  engine_->set_outline(shell_outline());
  if (!spec_.slab_depth) {
    engine_->add_wall(Wall::plane("end wall y-", Vec3::Zero(), Vec3::UnitY()));
    engine_->add_wall(Wall::plane("end wall y+", Vec3(0, spec_.length, 0), -Vec3::UnitY()));
  }
}

RainFillSettings DrumScene::rain() const {
  const double r = settings_.material.particle.radius;
  const double R = 0.5 * spec_.diameter;
  const double depth = slab_depth();
  RainFillSettings s;
  // Inside the drum from its bottom; across the whole periodic slab, or between the end walls.
  s.region_lower = Vec3(-(R - r), spec_.slab_depth ? 0.0 : r, -R + r);
  s.region_upper =
      Vec3(R - r, spec_.slab_depth ? depth : depth - r, -R + r + kDrumRegionHeight * r);
  s.follow_gap = kDrumFollowGap * r;
  s.radius = r;
  s.density = settings_.material.particle.density;
  const double fill_mass =
      spec_.fill_fraction * std::numbers::pi * R * R * depth * s.density * kPouredPacking;
  const double bed_height = fill_line() + R;
  s.mass_rate = fill_mass * kRainRiseSpeed / bed_height;
  s.target_mass = kRainSurplus * fill_mass;
  // Inserting also ends once the region would leave the drum (a fill fraction near 1).
  s.target_height = R - (kDrumFollowGap + 3.0) * r;
  s.initial_velocity = Vec3(0.0, 0.0, -kRainSpeed);
  s.insert_time_cap = 6.0 * kRainSurplus * bed_height / kRainRiseSpeed + 2.0;
  s.settle_speed = spec_.settle_speed;
  s.settle_time_cap = spec_.max_settle_time;
  s.trim_height = fill_line();
  s.seed = spec_.seed;
  s.admits = [R](const Vec3& x, double radius) { return std::hypot(x.x(), x.z()) <= R - radius; };
  return s;
}

DrumScene::DrumScene(DemSettings settings, DrumSceneSpec spec, DemCheckpoint checkpoint)
    : settings_(std::move(settings)), spec_(spec) {
  rotation_start_ = checkpoint.time;
  rebuild(std::move(checkpoint));
}

double DrumScene::fill_line() const {
  const FillSegment seg = fill_segment(spec_.diameter, spec_.fill_fraction);
  return -0.5 * spec_.diameter * std::cos(seg.half_angle);
}

SceneOutline DrumScene::shell_outline() const {
  return circle_outline(Vec3(0.0, 0.5 * slab_depth(), 0.0), Vec3::UnitY(), 0.5 * spec_.diameter);
}

double DrumScene::slab_depth() const { return spec_.slab_depth ? *spec_.slab_depth : spec_.length; }

void DrumScene::rebuild(DemCheckpoint checkpoint) {
  engine_ = std::make_unique<DemEngine>(settings_, std::move(checkpoint));
  engine_->set_outline(shell_outline());
  std::ostringstream quiet;
  engine_->prepare(quiet);
}

bool DrumScene::save_fill(Hdf5File& file) const { return rain_fill_ && rain_fill_->save(*engine_, file); }

void DrumScene::restore_fill(const Hdf5File& file) {
  rain_fill_.emplace(rain());
  rain_fill_->restore(*engine_, file);
}

const FillReport& DrumScene::fill(std::ostream& log, ProgressSink* progress) {
  if (!rain_fill_) rain_fill_.emplace(rain());
  rain_fill_->set_progress(progress);
  fill_report_ = rain_fill_->run(*engine_, log);
  if (fill_report_.interrupted) return fill_report_;
  engine_->run_steps(1);  // the list rebuilt after the trim: the bed can be checkpointed
  if (fill_report_.trimmed_count == 0)
    log << "drum: warning: the settled bed does not reach the fill line; the fill is below "
        << spec_.fill_fraction * 100 << " %\n";
  return fill_report_;
}

void DrumScene::start_rotation(std::ostream& log) {
  DemCheckpoint c = engine_->checkpoint();
  for (auto& w : c.walls)  // the end plates of the sealed drum turn with the shell
    w.moving(Vec3::Zero(), Vec3(0.0, spec_.speed, 0.0));
  const RunReport filling = engine_->report();
  rebuild(std::move(c));
  engine_->add_earlier_phases(filling);
  rotation_start_ = engine_->time();
  log << "drum: the shell turns at " << in_rpm(spec_.speed) << " rpm from t = "
      << rotation_start_ << " s\n";
}

DrumSample DrumScene::sample() const {
  // Each rank measures its own particles; sums, and the merged tops of the bed's columns, make
  // the whole bed's sample on every rank.
  const BedView bed = engine_->bed();
  const ParticleStore& p = bed.store();
  const std::size_t own = bed.own();
  const double r = settings_.material.particle.radius;
  const double R = 0.5 * spec_.diameter;
  const double omega = spec_.speed;
  DrumSample s;
  s.time = engine_->time() - rotation_start_;
  s.kinetic_energy = bed.kinetic_energy();
  const double count = bed.count();
  if (count == 0.0) return s;
  std::vector<SurfacePoint> section(own);
  for (std::size_t i = 0; i < own; ++i) section[i] = {p.position[i].x(), p.position[i].z()};
  s.surface = bed_surface_points(section, r, R, [&bed](ColumnTops& tops) {
    bed.highest(tops.z, tops.depth);
    bed.sum(tops.count);
  });
  const DrumSurfaceFit fit = fit_drum_surface(s.surface, R);
  s.valid = fit.valid;
  // The shell carries the bed towards -x for omega > 0 (bottom moving at -omega R x).
  s.angle = omega >= 0.0 ? -fit.slope_angle : fit.slope_angle;
  s.state.surface_bulge = fit.bulge;
  const double slope = std::tan(fit.slope_angle);
  // airborne, over the top, moving with the shell, beside the shell, their speed along it
  std::vector<double> tally(5, 0.0);
  for (std::size_t i = 0; i < own; ++i) {
    const Vec3& x = p.position[i];
    const Vec3& v = p.velocity[i];
    const double radial = std::hypot(x.x(), x.z());
    if (fit.valid && radial < R - 2.0 * r && x.z() > fit.intercept + slope * x.x() + 3.0 * r) ++tally[0];
    if (x.z() > 0.8 * R) ++tally[1];
    const Vec3 rigid(omega * x.z(), 0.0, -omega * x.x());  // omega y-hat x r
    if ((v - rigid).norm() < 0.1 * std::abs(omega) * R) ++tally[2];
    if (radial > R - 1.5 * r && radial > 0.0) {
      ++tally[3];
      tally[4] += (v.x() * x.z() - v.z() * x.x()) / radial;  // along omega y-hat x r-hat
    }
  }
  bed.sum(tally);
  const double airborne = tally[0], over_top = tally[1], solid = tally[2], shell = tally[3],
               shell_speed = tally[4];
  s.state.particles = count;
  s.state.airborne_fraction = airborne / count;
  s.state.over_top_fraction = over_top / count;
  s.state.solid_body_fraction = omega != 0.0 ? solid / count : 0.0;
  s.state.shell_speed_ratio =
      shell > 0 && omega != 0.0 ? shell_speed / shell / (omega * R) : 1.0;
  return s;
}

}  // namespace feedflow
