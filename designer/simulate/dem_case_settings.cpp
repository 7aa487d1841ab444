#include "designer/simulate/dem_case_settings.hpp"

#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

DemSettings dem_case_settings(const Case& c, const DemRanks& ranks) {
  if (!c.material.dem)
    throw InputError(c.file, "material", "material " + c.material.name +
                                             " has no [dem] parameters (seed Table 2); the DEM needs them");
  if (c.dem.stopping_layer && c.kind() != EquipmentKind::chute)
    throw InputError(c.file, "dem.stopping_layer",
                     "a stopping layer is an inclined plane's (chute's) scene; leave the key out");
  if (c.dem.stopping_layer_length && !c.dem.stopping_layer)
    throw InputError(c.file, "dem.stopping_layer_length",
                     "the periodic length of a stopping layer: set dem.stopping_layer too, or "
                     "leave the key out");
  DemSettings s;
  s.material = *c.material.dem;
  s.law = choose_contact_law(c.dem.normal_law, {}, {}, c.dem.cohesion);  // checked on loading
  if (c.dem.time_step) s.requested_time_step = *c.dem.time_step;
  s.force_time_step = c.dem.force_time_step == "yes";
  if (c.dem.time_step_safety) s.stable_step_fraction = *c.dem.time_step_safety;
  s.ranks = ranks;
  return s;
}

void require_slab_depth(const Case& c, const DemSettings& settings, double slab_depth) {
  const double r = settings.material.particle.radius;
  const double cutoff = 2.0 * r * (1.0 + settings.skin_fraction);
  if (slab_depth < 2.0 * cutoff)
    throw InputError(c.file, "dem.slab_depth",
                     "the periodic slab must be at least two neighbour cutoffs deep (" +
                         format_number(2.0 * cutoff * 1e3, 3) + " mm for R = " + format_number(r * 1e3, 3) + " mm)");
}

void add_time_step_warning(const DemEngine& engine, std::vector<std::string>& assumptions) {
  const std::string& warning = engine.time_step_choice().warning;
  if (!warning.empty())
    assumptions.push_back(warning.substr(warning.rfind("warning: ", 0) == 0 ? 9 : 0));
}

SlabFaces slab_faces_of(const Case& c) {
  const auto faces = slab_faces_from_keyword(c.dem.slab_faces);
  if (!faces)
    throw InputError(c.file, "dem.slab_faces",
                     "\"frictional\", \"frictionless\", \"periodic\" or \"planar\", not \"" + c.dem.slab_faces +
                         "\"");
  return *faces;
}

void require_periodic_faces(const Case& c, const std::string& scene) {
  const SlabFaces faces = slab_faces_of(c);
  if (faces == SlabFaces::frictional || faces == SlabFaces::frictionless ||
      faces == SlabFaces::planar)
    throw InputError(c.file, "dem.slab_faces",
                     "the DEM " + scene +
                         " slab is periodic (its walls are the scene's own); \"periodic\" "
                         "or leave the key out");
}

double dem_snapshot_interval(const Case& c, double duration, double sample_interval) {
  if (c.dem.snapshot_interval) return *c.dem.snapshot_interval;
  constexpr double kMostSnapshots = 50.0;
  const double samples = duration / (kMostSnapshots * sample_interval);  // per snapshot, at least
  for (double decade = 1.0;; decade *= 10.0)
    for (const double m : {1.0, 2.0, 5.0})
      if (m * decade >= samples * (1.0 - 1e-9)) return m * decade * sample_interval;
}

}  // namespace feedflow
