#include "fullsim/dem/scene/inclined_plane_scene.hpp"

#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

namespace feedflow {

namespace {

constexpr double kG = 9.81;

SimulationBox plane_box(const InclinedPlaneSpec& s, double r) {
  return SimulationBox{Vec3(-s.bin_length - 2.0 * r, 0.0, -2.0 * r),
                       Vec3(s.ramp_length + 4.0 * r, s.slab_depth, s.bin_height + 4.0 * r),
                       {false, true, false}};
}

// A rectangle x0..x1 (at heights z0..z1 along the way) spanning y over three slab depths.
void add_strip(TriangleMesh& m, const Vec3& a, const Vec3& b, double depth, std::size_t& n) {
  const Vec3 y0(0.0, -depth, 0.0), y1(0.0, 2.0 * depth, 0.0);
  m.add_triangle(a + y0, b + y0, b + y1, n++);
  m.add_triangle(a + y0, b + y1, a + y1, n++);
}

}  // namespace

InclinedPlaneScene::InclinedPlaneScene(DemSettings settings, InclinedPlaneSpec spec)
    : settings_(std::move(settings)), spec_(spec) {
  settings_.gravity = kG * Vec3(std::sin(spec_.angle), 0.0, -std::cos(spec_.angle));
  const double r = settings_.material.particle.radius;
  if (!(r > 0.0) || spec_.slab_depth < 4.0 * r || spec_.fill_height < 4.0 * r ||
      spec_.bin_length < 4.0 * r || spec_.gate_opening < 2.0 * r)
    throw std::invalid_argument("inclined plane: the slab, bin, fill and gate must hold a few particles");
  const double a = 1.04 * 2.0 * r;
  const int ny = std::max(2, static_cast<int>(std::floor(spec_.slab_depth / a)));
  const double ay = spec_.slab_depth / ny;
  const double top = std::min(1.3 * spec_.fill_height, spec_.bin_height - r);
  std::mt19937 rng(spec_.seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ParticleStore p;
  const double rho = settings_.material.particle.density;
  for (double z = 1.05 * r; z <= top; z += a)
    for (double x = -spec_.bin_length + 1.05 * r; x <= -1.05 * r; x += a)
      for (int j = 0; j < ny; ++j) {
        const Vec3 jitter = 0.02 * r * Vec3(u(rng), u(rng), u(rng));
        p.add(Vec3(x, (j + 0.5) * ay, z) + jitter, r, rho);
      }
  engine_ = std::make_unique<DemEngine>(settings_, plane_box(spec_, r), std::move(p));
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
  const double period = 2.0 * r, h = r, depth = spec_.slab_depth;
  TriangleMesh ramp;
  ramp.source = "saw-tooth ramp (45 deg faces, period 2R, height R)";
  std::size_t n = 0;
  for (double x = 0.0; x < spec_.ramp_length; x += period) {
    add_strip(ramp, Vec3(x, 0, 0), Vec3(x + 0.5 * period, 0, h), depth, n);
    add_strip(ramp, Vec3(x + 0.5 * period, 0, h), Vec3(x + period, 0, 0), depth, n);
  }
  e.add_mesh_wall(MeshWall("ramp", std::move(ramp)));
  TriangleMesh gate;
  gate.source = "lifted gate plate";
  n = 0;
  add_strip(gate, Vec3(0, 0, spec_.gate_opening), Vec3(0, 0, spec_.bin_height + 4.0 * r), depth, n);
  e.add_mesh_wall(MeshWall("lifted gate", std::move(gate)));
}

void InclinedPlaneScene::rebuild(DemCheckpoint checkpoint) {
  engine_ = std::make_unique<DemEngine>(settings_, std::move(checkpoint));
  add_meshes(*engine_);
  std::ostringstream quiet;
  engine_->prepare(quiet);
}

void InclinedPlaneScene::settle(std::ostream& log, const char* phase) {
  DemEngine& e = *engine_;
  const double start = e.time();
  while (e.time() - start < spec_.max_settle_time) {
    e.run_until(e.time() + 0.01);
    if (e.time() - start >= 0.1 && e.max_speed() < spec_.settle_speed) break;
  }
  log << "inclined plane: " << phase << " " << e.particles().size() << " particles, settled for "
      << e.time() - start << " s, largest speed " << e.max_speed() << " m/s\n";
}

void InclinedPlaneScene::fill(std::ostream& log) {
  engine_->prepare(log);
  settle(log, "packing fell:");
  const ParticleStore& p = engine_->particles();
  std::vector<char> above(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i) above[i] = p.position[i].z() > spec_.fill_height;
  engine_->remove_particles(above);
  settle(log, "trimmed to the fill height:");
}

void InclinedPlaneScene::open_gate(std::ostream& log) {
  release_time_ = engine_->time();
  engine_->set_wall_removal_time("gate", release_time_);
  log << "inclined plane: gate opened to " << spec_.gate_opening << " m at t = " << release_time_ << " s\n";
}

bool InclinedPlaneScene::flow_stopped() const {
  const ParticleStore& p = engine_->particles();
  if (p.size() == 0) return true;
  const double r = settings_.material.particle.radius;
  const double m = p.mass[0];
  return p.kinetic_energy() / static_cast<double>(p.size()) < 1e-3 * m * kG * 2.0 * r;
}

DepositProfile InclinedPlaneScene::deposit() const {
  return measure_deposit(engine_->particles(), spec_.ramp_length, ramp_surface(),
                         2.0 * settings_.material.particle.radius);
}

}  // namespace feedflow
