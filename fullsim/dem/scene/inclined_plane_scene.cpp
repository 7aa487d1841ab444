#include "fullsim/dem/scene/inclined_plane_scene.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fullsim/dem/scene/sawtooth_ramp.hpp"

namespace feedflow {

namespace {

constexpr double kG = 9.81;
// Rain-fall (rain_fill.hpp): the region's bottom rides kPlaneFollowGap radii above the resting fill
// and is kPlaneRegionHeight radii tall, and the spheres start normal to the ramp at kRainSpeed, so
// they land after ~0.02 s having drifted down the slope by ~0.5 g sin(angle) t^2, about 1 mm
// at 37 deg (falling along the tilted gravity they drifted ~16 mm for R = 3 mm, the heap leaned
// on the gate and the back quarter of the bin stayed empty: measured). The rate raises the bed
// by kRainRiseSpeed, which the region feeds without crowding.
constexpr double kPlaneFollowGap = 2.0;     // [R]
constexpr double kPlaneRegionHeight = 4.0;  // [R]

SimulationBox plane_box(const InclinedPlaneSpec& s, double r) {
  return SimulationBox{Vec3(-s.bin_length - 2.0 * r, 0.0, -2.0 * r),
                       Vec3(s.ramp_length + 4.0 * r, s.slab_depth, s.bin_height + 4.0 * r),
                       {false, true, false}};
}

}  // namespace

InclinedPlaneScene::InclinedPlaneScene(DemSettings settings, InclinedPlaneSpec spec)
    : settings_(std::move(settings)), spec_(spec) {
  settings_.gravity = kG * Vec3(std::sin(spec_.angle), 0.0, -std::cos(spec_.angle));
  const double r = settings_.material.particle.radius;
  if (!(r > 0.0) || spec_.slab_depth < 4.0 * r || spec_.fill_height < 4.0 * r ||
      spec_.bin_length < 4.0 * r || spec_.gate_opening < 2.0 * r)
    throw std::invalid_argument("inclined plane: the slab, bin, fill and gate must hold a few particles");
  engine_ = std::make_unique<DemEngine>(settings_, plane_box(spec_, r), ParticleStore{});
  engine_->add_wall(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  engine_->add_wall(Wall::plane("bin back wall", Vec3(-spec_.bin_length, 0, 0), Vec3::UnitX()));
  engine_->add_wall(Wall::plane("gate", Vec3::Zero(), -Vec3::UnitX()));
  engine_->set_outlet_sink(OutletSink::plane(Vec3(spec_.ramp_length, 0, 0), Vec3::UnitX()));
  add_meshes(*engine_);
}

InclinedPlaneScene::InclinedPlaneScene(DemSettings settings, InclinedPlaneSpec spec,
                                       DemCheckpoint checkpoint)
    : settings_(std::move(settings)), spec_(spec) {
  settings_.gravity = kG * Vec3(std::sin(spec_.angle), 0.0, -std::cos(spec_.angle));
  release_time_ = checkpoint.time;
  rebuild(std::move(checkpoint));
}

double InclinedPlaneScene::ramp_surface() const { return settings_.material.particle.radius; }

void InclinedPlaneScene::add_meshes(DemEngine& e) const {
  const double r = settings_.material.particle.radius;
  const double depth = spec_.slab_depth;
  e.add_mesh_wall(MeshWall("ramp", sawtooth_ramp(0.0, spec_.ramp_length, r, depth)));
  TriangleMesh gate;
  gate.source = "lifted gate plate";
  std::size_t n = 0;
  add_slab_strip(gate, Vec3(0, 0, spec_.gate_opening), Vec3(0, 0, spec_.bin_height + 4.0 * r),
                 depth, n);
  e.add_mesh_wall(MeshWall("lifted gate", std::move(gate)));
  // For pictures: the bin (back wall and floor), the lifted gate and the ramp, in the plane's
  // frame.
  const double y = 0.5 * depth, top = spec_.bin_height + 4.0 * r;
  e.set_outline({{Vec3(-spec_.bin_length, y, top), Vec3(-spec_.bin_length, y, 0.0)},
                 {Vec3(-spec_.bin_length, y, 0.0), Vec3(spec_.ramp_length, y, 0.0)},
                 {Vec3(0.0, y, spec_.gate_opening), Vec3(0.0, y, top)}});
}

void InclinedPlaneScene::rebuild(DemCheckpoint checkpoint) {
  engine_ = std::make_unique<DemEngine>(settings_, std::move(checkpoint));
  add_meshes(*engine_);
  std::ostringstream quiet;
  engine_->prepare(quiet);
}

RainFillSettings InclinedPlaneScene::rain() const {
  const double r = settings_.material.particle.radius;
  const InclinedPlaneSpec& p = spec_;
  RainFillSettings s;
  s.region_lower = Vec3(-p.bin_length + r, 0.0, r);
  s.region_upper = Vec3(-r, p.slab_depth, (1.0 + kPlaneRegionHeight) * r);
  s.follow_gap = kPlaneFollowGap * r;
  s.radius = r;
  s.density = settings_.material.particle.density;
  const double fill_mass = p.bin_length * p.fill_height * p.slab_depth * s.density * kPouredPacking;
  s.mass_rate = fill_mass * kRainRiseSpeed / p.fill_height;
  s.target_mass = kRainSurplus * fill_mass;
  // Inserting also ends once the region would rise out of the bin.
  s.target_height = p.bin_height - (kPlaneFollowGap + 3.0) * r;
  s.initial_velocity = Vec3(0.0, 0.0, -kRainSpeed);
  s.insert_time_cap = 6.0 * kRainSurplus * p.fill_height / kRainRiseSpeed + 2.0;
  s.settle_speed = p.settle_speed;
  s.settle_time_cap = p.max_settle_time;
  s.trim_height = p.fill_height;
  s.seed = p.seed;
  const double back = -p.bin_length, top = p.bin_height;
  s.admits = [back, top](const Vec3& x, double radius) {
    return x.x() >= back + radius && x.x() <= -radius && x.z() >= radius && x.z() <= top - radius;
  };
  return s;
}

bool InclinedPlaneScene::save_fill(Hdf5File& file) const { return rain_fill_ && rain_fill_->save(*engine_, file); }

void InclinedPlaneScene::restore_fill(const Hdf5File& file) {
  rain_fill_.emplace(rain());
  rain_fill_->restore(*engine_, file);
}

const FillReport& InclinedPlaneScene::fill(std::ostream& log, ProgressSink* progress) {
  if (!rain_fill_) rain_fill_.emplace(rain());
  rain_fill_->set_progress(progress);
  fill_report_ = rain_fill_->run(*engine_, log);
  return fill_report_;
}

void InclinedPlaneScene::open_gate(std::ostream& log) {
  release_time_ = engine_->time();
  engine_->set_wall_removal_time("gate", release_time_);
  log << "inclined plane: gate opened to " << spec_.gate_opening << " m at t = " << release_time_ << " s\n";
}

bool InclinedPlaneScene::flow_stopped() const {
  return bed_at_rest(engine_->bed(), 2.0 * settings_.material.particle.radius, kG);
}

DepositProfile InclinedPlaneScene::deposit() const {
  return measure_deposit(engine_->bed(), spec_.ramp_length, ramp_surface(),
                         2.0 * settings_.material.particle.radius);
}

}  // namespace feedflow
