#include "designer/calibrate/stopping_records.hpp"

#include "designer/calibrate/verified_record.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

StoppingRecord read_stopping_record(const std::filesystem::path& path, const std::string& material,
                                    const std::string& option) {
  const VerifiedRecord j = VerifiedRecord::read(path, option, "chute", material);
  const std::string file = path.string();
  StoppingRecord r;
  // The search's bracket when it reached its tolerance, else (no L3 stopping thickness) as far as
  // its layers went.
  std::string entry = "stopping_thickness";
  const std::string rung =
      j.text({"results", entry, "rung"}, "the rung that verified the stopping thickness");
  if (rung != "L3" && j.json["results"].contains(entry + "_so_far")) {
    entry += "_so_far";
    r.so_far = true;
  } else if (rung != "L3") {
    throw InputError(file, "results." + entry + ".rung",
                     "expected a stopping thickness bracketed on L3 (`feedflow design PLANE --set "
                     "chute.angle=ANGLE --verify dem`), got " +
                         rung);
  }
  const std::string key = "results." + entry;
  r.file = path;
  r.stops_at = j.number({"results", entry, "low"}, "the thickest layer that came to rest [m]");
  r.flows_at = j.number({"results", entry, "high"}, "the thinnest layer that flowed on [m]");
  if (!(r.stops_at > 0.0 && r.stops_at < r.flows_at))
    throw InputError(file, key, "expected a bracket: a layer that rested below one that flowed");
  r.observation.angle = j.number({"inputs", "chute", "angle"}, "the plane's angle [rad]");
  r.observation.reference = 0.5 * (r.stops_at + r.flows_at);
  r.observation.error_bar = 0.5 * (r.flows_at - r.stops_at);
  r.sphere_radius = j.sphere_radius();
  // "DEM (hysteretic_nonlinear2) periodic layers at 42 deg: rests at ..." -> the law, the rung in
  // words.
  const std::string model = j.text({"results", entry, "model"}, "the verifying model");
  r.law = j.dem_law(entry);
  r.rung = "L3 " + model.substr(0, model.find(" at "));
  r.commits = j.run_commits();
  r.command = path.filename().string();
  if (const auto p = j.json.find("provenance"); p != j.json.end() && p->is_object())
    if (const auto c = p->find("command_line"); c != p->end() && c->is_string())
      r.command = c->get<std::string>();
  return r;
}

}  // namespace feedflow
