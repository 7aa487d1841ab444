#include "designer/calibrate/arching_records.hpp"

#include "designer/calibrate/verified_record.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

ArchingRecord read_arching_record(const std::filesystem::path& path, const std::string& against,
                                  const std::string& material, const Hopper& hopper) {
  const VerifiedRecord j = VerifiedRecord::read(path, "--arching", "hopper", material);
  const std::string file = path.string();
  const std::string shape = j.text({"inputs", "hopper", "shape"}, "wedge or conical");
  if (shape != hopper.shape)
    throw InputError(file, "inputs.hopper.shape",
                     "expected the case's " + hopper.shape + ", got " + shape);

  const std::string width = "results.critical_outlet_width";
  const std::string rung =
      j.text({"results", "critical_outlet_width", "rung"}, "the rung that verified B_c");
  const std::string wanted = against == "dem" ? "L3" : "L2";
  if (rung != wanted)
    throw InputError(file, width + ".rung",
                     "expected a critical outlet width verified on " + wanted +
                         " (`feedflow design ... --verify " + against +
                         " --width-tolerance WIDTH`), got " + rung);
  ArchingRecord r;
  r.file = path;
  r.observation.hopper = hopper;
  r.observation.hopper.semi_angle =
      j.number({"inputs", "hopper", "semi_angle"}, "the semi-angle [rad]");
  r.observation.hopper.wall_friction_angle =
      j.number({"inputs", "hopper", "wall_friction_angle"}, "the wall friction angle [rad]");
  r.observation.arches_at =
      j.number({"results", "critical_outlet_width", "low"}, "the widest outlet that arched [m]");
  r.observation.flows_at = j.number({"results", "critical_outlet_width", "high"},
                                    "the narrowest outlet that flowed [m]");
  if (!(r.observation.arches_at > 0.0 && r.observation.arches_at < r.observation.flows_at))
    throw InputError(file, width,
                     "expected a bracket: an outlet that arched below one that flowed");
  const std::string model =
      j.text({"results", "critical_outlet_width", "model"}, "the verifying model");
  const std::size_t cut = model.find(" bisection: ");
  r.rung = rung + " " + model.substr(0, cut);
  r.bracket = cut == std::string::npos ? model : model.substr(cut + 12);
  r.commits = j.run_commits();
  return r;
}

}  // namespace feedflow
