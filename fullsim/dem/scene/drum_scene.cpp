#include "fullsim/dem/scene/drum_scene.hpp"

#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

#include "models/drum/drum_regime.hpp"

namespace feedflow {

namespace {

constexpr double kLatticeGap = 1.04;  // lattice spacing / particle diameter

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
  // Jittered lattice in the drum up to the fill line plus 0.6 R (the loose lattice, packing
  // 0.47, settles to about 0.6; the surplus is trimmed after settling).
  const double top = fill_line() + 0.6 * R;
  const double depth = slab_depth();
  const double a = kLatticeGap * 2.0 * r;
  // Along a periodic axis the layers may touch (spacing >= 2R, no jitter in y): a 3-diameter
  // slab holds 3 layers, not 2 at the x-z spacing.
  const int ny = spec_.slab_depth ? std::max(2, static_cast<int>(std::floor(depth / (2.0 * r) + 1e-9)))
                                  : static_cast<int>(std::floor((depth - 2.1 * r) / a)) + 1;
  const double ay = spec_.slab_depth ? depth / ny : a;
  const double y0 = spec_.slab_depth ? 0.5 * ay : r * 1.05;
  std::mt19937 rng(spec_.seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ParticleStore p;
  const double rho = settings_.material.particle.density;
  for (double z = -R + 1.05 * r; z <= top; z += a)
    for (double x = -R + 1.05 * r; x <= R - r; x += a) {
      if (std::hypot(x, z) > R - 1.1 * r) continue;
      for (int j = 0; j < ny; ++j) {
        const Vec3 jitter = 0.02 * r * Vec3(u(rng), 0.0, u(rng));
        p.add(Vec3(x, y0 + j * ay, z) + jitter, r, rho, 0.0, 0.05 * Vec3(u(rng), u(rng), u(rng)));
      }
    }
  engine_ = std::make_unique<DemEngine>(settings_, drum_box(spec_, r), std::move(p));
  engine_->add_wall(Wall::cylinder("shell", Vec3::Zero(), Vec3::UnitY(), R, true));
  if (!spec_.slab_depth) {
    engine_->add_wall(Wall::plane("end wall y-", Vec3::Zero(), Vec3::UnitY()));
    engine_->add_wall(Wall::plane("end wall y+", Vec3(0, spec_.length, 0), -Vec3::UnitY()));
  }
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

double DrumScene::slab_depth() const { return spec_.slab_depth ? *spec_.slab_depth : spec_.length; }

void DrumScene::rebuild(DemCheckpoint checkpoint) {
  engine_ = std::make_unique<DemEngine>(settings_, std::move(checkpoint));
  std::ostringstream quiet;
  engine_->prepare(quiet);
}

void DrumScene::settle(std::ostream& log, const char* phase) {
  DemEngine& e = *engine_;
  const double start = e.time();
  const double chunk = 0.01;
  while (e.time() - start < spec_.max_settle_time) {
    e.run_until(e.time() + chunk);
    if (e.time() - start >= 0.1 && e.max_speed() < spec_.settle_speed) break;
  }
  log << "drum: " << phase << " " << e.particles().size() << " particles, settled for "
      << e.time() - start << " s, largest speed " << e.max_speed() << " m/s\n";
}

void DrumScene::fill(std::ostream& log) {
  engine_->prepare(log);
  settle(log, "packing fell:");
  // Trim above the fill line: an outlet sink beyond the fill plane for one step.
  DemCheckpoint c = engine_->checkpoint();
  c.sink = OutletSink::plane(Vec3(0, 0, fill_line()), Vec3::UnitZ());
  rebuild(std::move(c));
  const std::size_t before = engine_->particles().size();
  engine_->run_steps(1);
  trimmed_ = before - engine_->particles().size();
  if (trimmed_ == 0)
    log << "drum: warning: the settled bed does not reach the fill line; the fill is below "
        << spec_.fill_fraction * 100 << " %\n";
  DemCheckpoint trimmed = engine_->checkpoint();
  trimmed.sink.reset();
  rebuild(std::move(trimmed));
  settle(log, "trimmed to the fill line:");
}

void DrumScene::start_rotation(std::ostream& log) {
  DemCheckpoint c = engine_->checkpoint();
  for (auto& w : c.walls)  // the end plates of the sealed drum turn with the shell
    w.moving(Vec3::Zero(), Vec3(0.0, spec_.speed, 0.0));
  rebuild(std::move(c));
  rotation_start_ = engine_->time();
  log << "drum: the shell turns at " << spec_.speed * 30.0 / 3.141592653589793 << " rpm from t = "
      << rotation_start_ << " s\n";
}

DrumSample DrumScene::sample() const {
  const ParticleStore& p = engine_->particles();
  const double r = settings_.material.particle.radius;
  const double R = 0.5 * spec_.diameter;
  const double omega = spec_.speed;
  DrumSample s;
  s.time = engine_->time() - rotation_start_;
  s.kinetic_energy = p.kinetic_energy();
  const std::size_t n = p.size();
  if (n == 0) return s;
  std::vector<SurfacePoint> section(n);
  for (std::size_t i = 0; i < n; ++i) section[i] = {p.position[i].x(), p.position[i].z()};
  s.surface = bed_surface_points(section, r, R);
  const DrumSurfaceFit fit = fit_drum_surface(s.surface, R);
  s.valid = fit.valid;
  // The shell carries the bed towards -x for omega > 0 (bottom moving at -omega R x).
  s.angle = omega >= 0.0 ? -fit.slope_angle : fit.slope_angle;
  s.state.surface_bulge = fit.bulge;
  const double slope = std::tan(fit.slope_angle);
  std::size_t airborne = 0, over_top = 0, solid = 0, shell = 0;
  double shell_speed = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = p.position[i];
    const Vec3& v = p.velocity[i];
    const double radial = std::hypot(x.x(), x.z());
    if (fit.valid && radial < R - 2.0 * r && x.z() > fit.intercept + slope * x.x() + 3.0 * r) ++airborne;
    if (x.z() > 0.8 * R) ++over_top;
    const Vec3 rigid(omega * x.z(), 0.0, -omega * x.x());  // omega y-hat x r
    if ((v - rigid).norm() < 0.1 * std::abs(omega) * R) ++solid;
    if (radial > R - 1.5 * r && radial > 0.0) {
      ++shell;
      shell_speed += (v.x() * x.z() - v.z() * x.x()) / radial;  // along omega y-hat x r-hat
    }
  }
  const double count = static_cast<double>(n);
  s.state.particles = count;
  s.state.airborne_fraction = airborne / count;
  s.state.over_top_fraction = over_top / count;
  s.state.solid_body_fraction = omega != 0.0 ? solid / count : 0.0;
  s.state.shell_speed_ratio =
      shell > 0 && omega != 0.0 ? shell_speed / static_cast<double>(shell) / (omega * R) : 1.0;
  return s;
}

}  // namespace feedflow
