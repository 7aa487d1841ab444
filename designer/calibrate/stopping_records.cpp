#include "designer/calibrate/stopping_records.hpp"

#include "designer/calibrate/verified_record.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

StoppingRecord read_stopping_record(const std::filesystem::path& path,
                                    const std::string& material) {
  const VerifiedRecord j = VerifiedRecord::read(path, "--stopping", "chute", material);
  const std::string file = path.string();
  const std::string key = "results.stopping_thickness";
  const std::string rung = j.text({"results", "stopping_thickness", "rung"},
                                  "the rung that verified the stopping thickness");
  if (rung != "L3")
    throw InputError(file, key + ".rung",
                     "expected a stopping thickness bracketed on L3 (`feedflow design PLANE --set "
                     "chute.angle=ANGLE --verify dem`), got " +
                         rung);
  StoppingRecord r;
  r.file = path;
  r.stops_at = j.number({"results", "stopping_thickness", "low"},
                        "the thickest layer that came to rest [m]");
  r.flows_at =
      j.number({"results", "stopping_thickness", "high"}, "the thinnest layer that flowed on [m]");
  if (!(r.stops_at > 0.0 && r.stops_at < r.flows_at))
    throw InputError(file, key, "expected a bracket: a layer that rested below one that flowed");
  r.observation.angle = j.number({"inputs", "chute", "angle"}, "the plane's angle [rad]");
  r.observation.reference = 0.5 * (r.stops_at + r.flows_at);
  r.observation.error_bar = 0.5 * (r.flows_at - r.stops_at);
  // "DEM (hysteretic_nonlinear2) periodic layers at 42 deg: rests at ..." -> the rung in words.
  const std::string model =
      j.text({"results", "stopping_thickness", "model"}, "the verifying model");
  r.rung = rung + " " + model.substr(0, model.find(" at "));
  r.commits = j.run_commits();
  r.command = path.filename().string();
  if (const auto p = j.json.find("provenance"); p != j.json.end() && p->is_object())
    if (const auto c = p->find("command_line"); c != p->end() && c->is_string())
      r.command = c->get<std::string>();
  return r;
}

}  // namespace feedflow
