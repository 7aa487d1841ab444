#include "designer/simulate/dem_hopper_scene.hpp"

#include <cstdio>
#include <numbers>

#include "designer/simulate/dem_case_settings.hpp"
#include "fullsim/common/discharge_measurement.hpp"
#include "models/core/errors.hpp"
#include "models/core/printf_format.hpp"

namespace feedflow {

double DemHopperScene::scale() const {
  if (const WedgeHopperSlab* w = slab()) return slot_length / w->depth;
  return 1.0 / std::get<ConicalHopper>(geometry).share();
}

double DemHopperScene::filled_volume() const {
  return std::visit([](const auto& g) { return g.fill_mass(1.0, 1.0); }, geometry);
}

double DemHopperScene::radius() const {
  return std::visit([](const auto& g) { return g.radius; }, geometry);
}

double DemHopperScene::outlet_size() const {
  if (const WedgeHopperSlab* w = slab()) return w->outlet_width;
  return std::get<ConicalHopper>(geometry).outlet_diameter;
}

double DemHopperScene::transition_height() const {
  return std::visit([](const auto& g) { return g.bin_bottom(); }, geometry);
}

double DemHopperScene::outlet_rate_scale(double bulk_density) const {
  const double d = outlet_size();
  if (const WedgeHopperSlab* w = slab()) return w->depth * outlet_scale_rate(bulk_density, d);
  return 0.25 * std::numbers::pi * d * outlet_scale_rate(bulk_density, d) / scale();
}

ProfileOffset DemHopperScene::profile_offset() const {
  return slab() ? ProfileOffset::across_x : ProfileOffset::from_axis;
}

SimulationBox DemHopperScene::box() const {
  return std::visit([](const auto& g) { return g.box(); }, geometry);
}

void DemHopperScene::add_walls(DemEngine& engine) const {
  std::visit([&engine](const auto& g) { g.add_walls(engine); }, geometry);
}

RainFillSettings DemHopperScene::rain() const {
  return std::visit([this](const auto& g) { return g.rain(density, bands, seed); }, geometry);
}

std::string DemHopperScene::describe() const {
  return std::visit([](const auto& g) { return g.describe(); }, geometry);
}

std::string DemHopperScene::model_text() const {
  if (const WedgeHopperSlab* w = slab())
    return format("DEM slab %.3g mm deep (rung L3), scaled x %.4g (slot length %.4g m / slab depth)",
                  w->depth * 1e3, scale(), slot_length);
  return "DEM (rung L3), " + std::get<ConicalHopper>(geometry).simulated_part();
}

namespace {

constexpr const char* kSceneName = "DEM hopper";  // a wedge slab or a cone

bool is_hopper_checkpoint(const Hdf5File& f) {
  if (f.exists("/scene/initial_ids")) return true;  // written before the scene was named
  try {
    return f.string_attribute("/scene", "scene") == kSceneName;
  } catch (const std::exception&) {
    return false;
  }
}

// A geometry's own check names the key; the case file is added here.
template <class Geometry>
void check_geometry(const Case& c, const Geometry& g) {
  try {
    g.check();
  } catch (const InputError& e) {
    if (!e.where().empty()) throw;
    throw InputError(c.file, e.key(), e.message());
  }
}

}  // namespace

DemHopperScene hopper_scene_from_case(const Case& c) {
  const Hopper& h = std::get<Hopper>(c.equipment);
  if (!c.material.dem)
    throw InputError(c.file, "material.dem",
                     "the material '" + c.material.name + "' has no [dem] parameters (Table 2)");
  DemHopperScene s;
  s.settings = dem_case_settings(c);
  s.density = c.material.dem->particle.density;
  const double r = c.material.dem->particle.radius;
  auto refused = [&c](const char* key, const char* what) {
    throw InputError(c.file, key, what);
  };
  if (h.is_wedge()) {
    if (c.dem.sector_angle) refused("dem.sector_angle", "a sector is of a conical hopper; a wedge runs as a slab");
    WedgeHopperSlab slab{h.semi_angle, h.outlet_width, h.bin_width, h.fill_height,
                         c.dem.slab_depth.value_or(2.0 * r), r, s.settings.skin_fraction};
    slab.faces = slab_faces_of(c);
    check_geometry(c, slab);
    if (!h.slot_length) refused("hopper.slot_length", "the wedge needs its slot length");
    s.slot_length = *h.slot_length;
    s.geometry = slab;
  } else {
    if (c.dem.slab_depth) refused("dem.slab_depth", "a conical hopper runs in 3D (whole or [dem] sector_angle), not as a slab");
    if (!c.dem.slab_faces.empty()) refused("dem.slab_faces", "a conical hopper runs in 3D; its sector's sides are frictionless symmetry planes");
    const ConicalHopper cone{h.semi_angle, h.outlet_width, h.bin_width, h.fill_height,
                             c.dem.sector_angle.value_or(2.0 * std::numbers::pi), r};
    check_geometry(c, cone);
    s.geometry = cone;
  }
  s.seed = static_cast<std::uint64_t>(c.dem.random_seed.value_or(1.0));
  if (c.dem.end_time) s.default_duration = *c.dem.end_time;
  return s;
}

void save_hopper_scene(const DemHopperScene& s, Hdf5File& f) {
  f.set_attribute("/scene", "scene", std::string(kSceneName));
  f.set_attribute("/scene", "opening_time", s.opening_time);
  f.set_attribute("/scene", "opening_step", static_cast<std::int64_t>(s.opening_step));
  f.set_attribute("/scene", "inserted_mass", s.fill.inserted_mass);
  f.set_attribute("/scene", "inserted_count", static_cast<std::int64_t>(s.fill.inserted_count));
  f.set_attribute("/scene", "trimmed_mass", s.fill.trimmed_mass);
  f.set_attribute("/scene", "trimmed_count", static_cast<std::int64_t>(s.fill.trimmed_count));
  f.set_attribute("/scene", "sunk_mass", s.fill.sunk_mass);
  f.set_attribute("/scene", "sunk_count", static_cast<std::int64_t>(s.fill.sunk_count));
  f.set_attribute("/scene", "settled", static_cast<std::int64_t>(s.fill.settled));
  if (const WedgeHopperSlab* slab = s.slab()) {
    f.set_attribute("/scene", "slab_depth", slab->depth);
    f.set_attribute("/scene", "slab_faces", std::string(to_string(slab->built_faces())));
  }
  f.set_attribute("/scene", "geometry", s.describe());
}

void restore_hopper_scene(DemHopperScene& s, const Hdf5File& f) {
  if (!is_hopper_checkpoint(f))
    throw InputError("--restart", "", f.path().string() + " is not a checkpoint of a DEM hopper scene");
  if (const WedgeHopperSlab* slab = s.slab()) {
    if (f.double_attribute("/scene", "slab_depth") != slab->depth)
      throw InputError("--restart", "", "the checkpoint's slab depth differs from the case's [dem] slab_depth");
    if (f.string_attribute("/scene", "slab_faces") != to_string(slab->built_faces()))
      throw InputError("--restart", "",
                       "the checkpoint's slab faces are " + f.string_attribute("/scene", "slab_faces") +
                           ", the case's [dem] slab_faces give " + to_string(slab->built_faces()));
  } else if (f.string_attribute("/scene", "geometry") != s.describe()) {
    throw InputError("--restart", "",
                     "the checkpoint holds another hopper:\n" + f.string_attribute("/scene", "geometry") +
                         "the case gives:\n" + s.describe());
  }
  s.opening_time = f.double_attribute("/scene", "opening_time");
  s.opening_step = static_cast<long>(f.integer_attribute("/scene", "opening_step"));
  s.fill.inserted_mass = f.double_attribute("/scene", "inserted_mass");
  s.fill.inserted_count = static_cast<std::size_t>(f.integer_attribute("/scene", "inserted_count"));
  s.fill.trimmed_mass = f.double_attribute("/scene", "trimmed_mass");
  s.fill.trimmed_count = static_cast<std::size_t>(f.integer_attribute("/scene", "trimmed_count"));
  s.fill.sunk_mass = f.double_attribute("/scene", "sunk_mass");
  s.fill.sunk_count = static_cast<std::size_t>(f.integer_attribute("/scene", "sunk_count"));
  s.fill.settled = f.integer_attribute("/scene", "settled") != 0;
  s.fill.target_reached = true;
}

void describe_hopper_scene(const DemHopperScene& s, std::ostream& log) {
  log << "DEM hopper scene (seed 3.1):\n" << s.describe();
  if (s.slab())
    log << "  skipped: the 3D rig (a slab; masses x " << s.scale()
        << " = slot length / slab depth), the sliding side walls (a gate plane removed at the "
           "opening), the fall below the outlet (particles deleted 5 R under it, mass booked), "
           "the run after q_m has converged (95 % interval within +-5 %), an arch or emptying\n";
  else
    log << "  skipped: the gate's motion (a plane removed at the opening), the fall below the outlet "
           "(particles deleted 5 R under it, mass booked), the run after q_m has converged (95 % "
           "interval within +-5 %), an arch or emptying\n";
}

DemEngine hopper_scene_structure(const DemHopperScene& s) {
  DemEngine engine(s.settings, s.box(), ParticleStore{});
  s.add_walls(engine);
  return engine;
}

bool save_hopper_fill(const DemHopperScene& s, const DemEngine& engine, Hdf5File& file) {
  return s.rain_fill && s.rain_fill->save(engine, file);
}

void restore_hopper_fill(DemHopperScene& s, DemEngine& engine, const Hdf5File& file) {
  s.rain_fill.emplace(s.rain());
  s.rain_fill->restore(engine, file);
}

bool fill_hopper_scene(DemHopperScene& s, DemEngine& engine, ProgressSink* progress, std::ostream& log) {
  if (!s.rain_fill) s.rain_fill.emplace(s.rain());
  s.rain_fill->set_progress(progress);
  s.fill = s.rain_fill->run(engine, log);
  if (s.fill.interrupted) return false;
  // The gate goes at the next step; the bands are frozen as they are now.
  s.opening_time = engine.time();
  s.opening_step = engine.step();
  engine.set_wall_removal_time("gate", s.opening_time);
  // (each particle keeps its band in its layer, and the sink books it with the particle)
  const BedView bed = engine.bed();
  char line[200];
  std::snprintf(line, sizeof line, "  gate removed at t = %.4g s (step %ld), %.0f particles, %.6g kg in the hopper (as simulated)\n",
                s.opening_time, s.opening_step, bed.count(), bed.total_mass());
  log << line;
  return true;
}

}  // namespace feedflow
