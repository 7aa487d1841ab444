#include "fullsim/dem/scene/stopping_layer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "fullsim/dem/scene/deposit_profile.hpp"
#include "fullsim/dem/scene/sawtooth_ramp.hpp"

namespace feedflow {

namespace {

constexpr double kLayerG = 9.81;
constexpr double kDefaultLengthDiameters = 20.0;
// The rain's region rides kLayerFollowGap radii above the resting fill and is
// kLayerRegionHeight radii tall, as on the plane's bin.
constexpr double kLayerFollowGap = 2.0;     // [R]
constexpr double kLayerRegionHeight = 4.0;  // [R]

// The periodic length in whole teeth (one diameter each), at least four.
double whole_teeth(double length, double r) {
  const double period = 2.0 * r;
  const double wanted = length > 0.0 ? length : kDefaultLengthDiameters * period;
  return std::max(4.0, std::round(wanted / period)) * period;
}

double box_top(const StoppingLayerSpec& s, double r) {
  // The rain's region at its highest, and room for a flowing layer to dilate.
  return r + kRainSurplus * s.thickness + (kLayerFollowGap + kLayerRegionHeight + 6.0) * r;
}

Vec3 ramp_gravity(double angle) { return kLayerG * Vec3(std::sin(angle), 0.0, -std::cos(angle)); }

}  // namespace

StoppingLayerScene::StoppingLayerScene(DemSettings settings, StoppingLayerSpec spec)
    : settings_(std::move(settings)), spec_(spec) {
  const double r = settings_.material.particle.radius;
  if (!(r > 0.0) || !(spec_.thickness >= 2.0 * r) || spec_.slab_depth < 4.0 * r)
    throw std::invalid_argument(
        "stopping layer: the layer must be a diameter thick and the slab two deep");
  if (!(spec_.angle >= 0.0 && spec_.angle < 0.5 * std::numbers::pi))
    throw std::invalid_argument("stopping layer: the angle must lie in [0, 90) deg");
  length_ = whole_teeth(spec_.length, r);
  settings_.gravity = Vec3(0.0, 0.0, -kLayerG);
  const SimulationBox box{Vec3(0.0, 0.0, -2.0 * r),
                          Vec3(length_, spec_.slab_depth, box_top(spec_, r)),
                          {true, true, false}};
  engine_ = std::make_unique<DemEngine>(settings_, box, ParticleStore{});
  // Two teeth beyond each end: the images of the periodic layer meet the ramp there too.
  engine_->add_mesh_wall(
      MeshWall("ramp", sawtooth_ramp(-4.0 * r, length_ + 4.0 * r, r, spec_.slab_depth)));
  const double y = 0.5 * spec_.slab_depth, crest = r;
  engine_->set_outline(
      {{Vec3(0.0, y, crest), Vec3(length_, y, crest)},
       {Vec3(0.0, y, crest + spec_.thickness), Vec3(length_, y, crest + spec_.thickness)}});
}

RainFillSettings StoppingLayerScene::rain() const {
  const double r = settings_.material.particle.radius, h = spec_.thickness;
  RainFillSettings s;
  s.region_lower = Vec3(0.0, 0.0, 2.0 * r);
  s.region_upper = Vec3(length_, spec_.slab_depth, (2.0 + kLayerRegionHeight) * r);
  s.follow_gap = kLayerFollowGap * r;
  s.radius = r;
  s.density = settings_.material.particle.density;
  const double fill_mass = length_ * spec_.slab_depth * h * s.density * kPouredPacking;
  s.mass_rate = fill_mass * kRainRiseSpeed / h;
  s.target_mass = kRainSurplus * fill_mass;
  // Inserting also ends once the region would rise out of the box.
  s.target_height = box_top(spec_, r) - (kLayerFollowGap + kLayerRegionHeight + 1.0) * r;
  s.initial_velocity = Vec3(0.0, 0.0, -kRainSpeed);
  s.insert_time_cap = 6.0 * kRainSurplus * h / kRainRiseSpeed + 2.0;
  s.settle_speed = spec_.settle_speed;
  s.settle_time_cap = spec_.max_settle_time;
  s.trim_height = h;  // centres up to h - R above the crests: tops up to h
  s.seed = spec_.seed;
  return s;
}

const FillReport& StoppingLayerScene::fill(std::ostream& log, ProgressSink* progress) {
  RainFill rain_fill(rain());
  rain_fill.set_progress(progress);
  fill_report_ = rain_fill.run(*engine_, log);
  return fill_report_;
}

void StoppingLayerScene::launch(std::ostream& log) {
  const double start = engine_->time(),
               target = spec_.launch_froude * std::sqrt(kLayerG * spec_.thickness);
  engine_->set_gravity(ramp_gravity(spec_.launch_angle));
  double u = 0.0;
  while ((u = downslope_speed()) < target && engine_->time() - start < 1.0)
    engine_->advance_to(engine_->time() + 0.002);
  if (u < target)
    throw std::runtime_error(
        "stopping layer: the launch ramp did not set the layer flowing (mean speed " +
        std::to_string(u) + " m/s after 1 s)");
  tilt_time_ = engine_->time();
  launch_speed_ = u;
  tilt();
  log << "stopping layer: launched at " << spec_.launch_angle * 180.0 / std::numbers::pi
      << " deg to " << u << " m/s in " << tilt_time_ - start << " s, then tilted to "
      << spec_.angle * 180.0 / std::numbers::pi << " deg at t = " << tilt_time_ << " s\n";
}

void StoppingLayerScene::tilt() { engine_->set_gravity(ramp_gravity(spec_.angle)); }

void StoppingLayerScene::resume(double tilt_time, double launch_speed) {
  tilt_time_ = tilt_time;
  launch_speed_ = launch_speed;
}

bool StoppingLayerScene::at_rest() const {
  return bed_at_rest(engine_->bed(), 2.0 * settings_.material.particle.radius, kLayerG);
}

bool StoppingLayerScene::runs_away() const {
  return downslope_speed() >= kRunAwaySpeedRatio * launch_speed_;
}

double StoppingLayerScene::downslope_speed() const {
  const BedView bed = engine_->bed();
  const ParticleStore& p = bed.store();
  double momentum = 0.0;
  for (std::size_t i = 0; i < bed.own(); ++i) momentum += p.mass[i] * p.velocity[i].x();
  const double mass = bed.total_mass();
  momentum = bed.sum(momentum);
  return mass > 0.0 ? momentum / mass : 0.0;
}

double StoppingLayerScene::thickness() const {
  const double r = settings_.material.particle.radius, crest = r;
  const BedView bed = engine_->bed();
  const ParticleStore& p = bed.store();
  const SimulationBox& box = engine_->box();
  const std::size_t bins = static_cast<std::size_t>(std::lround(length_ / (2.0 * r)));
  std::vector<double> top(bins, 0.0);
  for (std::size_t i = 0; i < bed.own(); ++i) {
    const Vec3 x = box.wrap(p.position[i]);
    const std::size_t b =
        std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, x.x() / (2.0 * r))));
    top[b] = std::max(top[b], x.z() + p.radius[i] - crest);
  }
  bed.max(top);
  double sum = 0.0;
  for (double t : top) sum += t;
  return sum / static_cast<double>(bins);
}

namespace {

// The mean of `speed_column` over the rows whose `time_column` lies in [from, to]; 0 without one.
double mean_over(const TimeSeries& series, std::size_t time_column, std::size_t speed_column,
                 double from, double to) {
  double sum = 0.0;
  int n = 0;
  for (const auto& row : series.rows())
    if (row[time_column] >= from && row[time_column] <= to) {
      sum += row[speed_column];
      ++n;
    }
  return n > 0 ? sum / n : 0.0;
}

}  // namespace

double layer_slowing_ratio(const TimeSeries& series, std::size_t time_column,
                           std::size_t speed_column, double t) {
  const double earlier =
      mean_over(series, time_column, speed_column, t - kLayerSlowingLag - kLayerSlowingWindow,
                t - kLayerSlowingLag);
  return earlier > 0.0
             ? mean_over(series, time_column, speed_column, t - kLayerSlowingWindow, t) / earlier
             : 1.0;
}

LayerOutcome run_layer(StoppingLayerScene& layer, double max_time, std::ostream& log,
                       double sample) {
  LayerOutcome o;
  DemEngine& e = layer.engine();
  const double t0 = layer.tilt_time();
  double next_line = 0.0;
  while (true) {
    e.advance_to(e.time() + sample);
    const double t = e.time() - t0, u = layer.downslope_speed();
    o.peak_speed = std::max(o.peak_speed, u);
    o.time = t;
    o.speed = u;
    if (t >= 0.1 && layer.at_rest()) {
      o.at_rest = true;
      break;
    }
    if (layer.runs_away()) {
      o.ran_away = true;
      break;
    }
    if (t >= max_time) break;
    if (t >= next_line) {
      log << "stopping layer: " << t << " s after the tilt, mean speed down the slope " << u
          << " m/s\n";
      next_line += 0.1 * max_time;
    }
  }
  o.thickness = layer.thickness();
  log << "stopping layer: "
      << (o.at_rest    ? "at rest"
          : o.ran_away ? "run away (flows on)"
                       : "still moving")
      << " " << o.time << " s after the tilt (mean speed " << o.speed << " m/s, peak "
      << o.peak_speed << " m/s), thickness " << o.thickness << " m\n";
  return o;
}

}  // namespace feedflow
