#include "designer/simulate/dem_hopper_scene.hpp"

#include <cstdio>

#include "designer/simulate/dem_case_settings.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

DemHopperScene hopper_scene_from_case(const Case& c) {
  const Hopper& h = std::get<Hopper>(c.equipment);
  if (!h.is_wedge())
    throw NotAvailable("the DEM hopper scene is a wedge (plane-flow) slab; a conical hopper "
                       "needs the 3D scene, which is not in this build");
  if (!c.material.dem)
    throw InputError(c.file, "material.dem",
                     "the material '" + c.material.name + "' has no [dem] parameters (Table 2)");
  DemHopperScene s;
  s.settings = dem_case_settings(c);
  s.density = c.material.dem->particle.density;
  const double r = c.material.dem->particle.radius;
  s.slab = WedgeHopperSlab{h.semi_angle, h.outlet_width, h.bin_width, h.fill_height,
                           c.dem.slab_depth.value_or(2.0 * r), r, s.settings.skin_fraction};
  s.slab.faces = slab_faces_of(c);
  s.slab.check();
  if (!h.slot_length) throw InputError(c.file, "hopper.slot_length", "the wedge needs its slot length");
  s.slot_length = *h.slot_length;
  s.seed = static_cast<std::uint64_t>(c.dem.random_seed.value_or(1.0));
  if (c.dem.end_time) s.default_duration = *c.dem.end_time;
  return s;
}

namespace {

constexpr const char* kSceneName = "DEM wedge hopper slab";

bool is_hopper_checkpoint(const Hdf5File& f) {
  if (f.exists("/scene/initial_ids")) return true;  // written before the scene was named
  try {
    return f.string_attribute("/scene", "scene") == kSceneName;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

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
  f.set_attribute("/scene", "slab_depth", s.slab.depth);
  f.set_attribute("/scene", "slab_faces", std::string(to_string(s.slab.built_faces())));
}

void restore_hopper_scene(DemHopperScene& s, const Hdf5File& f) {
  if (!is_hopper_checkpoint(f))
    throw InputError("--restart", "", f.path().string() + " is not a checkpoint of a DEM hopper scene");
  if (f.double_attribute("/scene", "slab_depth") != s.slab.depth)
    throw InputError("--restart", "", "the checkpoint's slab depth differs from the case's [dem] slab_depth");
  if (f.string_attribute("/scene", "slab_faces") != to_string(s.slab.built_faces()))
    throw InputError("--restart", "",
                     "the checkpoint's slab faces are " +
                         f.string_attribute("/scene", "slab_faces") +
                         ", the case's [dem] slab_faces give " + to_string(s.slab.built_faces()));
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
  log << "DEM hopper scene (seed 3.1):\n" << s.slab.describe();
  log << "  skipped: the 3D rig (a slab; masses x " << s.depth_scale()
      << " = slot length / slab depth), the sliding side walls (a gate plane removed at the "
         "opening), the fall below the outlet (particles deleted 5 R under it, mass booked), "
         "the run after q_m has converged (95 % interval within +-5 %), an arch or emptying\n";
}

DemEngine hopper_scene_structure(const DemHopperScene& s) {
  DemEngine engine(s.settings, s.slab.box(), ParticleStore{});
  s.slab.add_walls(engine);
  return engine;
}

bool save_hopper_fill(const DemHopperScene& s, const DemEngine& engine, Hdf5File& file) {
  return s.rain_fill && s.rain_fill->save(engine, file);
}

void restore_hopper_fill(DemHopperScene& s, DemEngine& engine, const Hdf5File& file) {
  s.rain_fill.emplace(s.slab.rain(s.density, s.bands, s.seed));
  s.rain_fill->restore(engine, file);
}

bool fill_hopper_scene(DemHopperScene& s, DemEngine& engine, ProgressSink* progress, std::ostream& log) {
  if (!s.rain_fill) s.rain_fill.emplace(s.slab.rain(s.density, s.bands, s.seed));
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
  std::snprintf(line, sizeof line, "  gate removed at t = %.4g s (step %ld), %.0f particles, %.6g kg in the slab\n",
                s.opening_time, s.opening_step, bed.count(), bed.total_mass());
  log << line;
  return true;
}

}  // namespace feedflow
