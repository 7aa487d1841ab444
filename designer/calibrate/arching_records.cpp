#include "designer/calibrate/arching_records.hpp"

#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/core/errors.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

using Json = nlohmann::ordered_json;

std::string joined(const std::vector<std::string>& keys) {
  std::string path;
  for (const auto& k : keys) (path += path.empty() ? "" : ".") += k;
  return path;
}

// The value under `keys` (a key may hold a dot: "material.name"), or an InputError naming the path.
const Json& at(const Json& j, const std::string& file, const std::vector<std::string>& keys,
               const std::string& expected) {
  const Json* node = &j;
  for (const auto& k : keys) {
    if (!node->is_object() || !node->contains(k) || (*node)[k].is_null())
      throw InputError(file, joined(keys), "expected " + expected);
    node = &(*node)[k];
  }
  return *node;
}

double number_at(const Json& j, const std::string& file, const std::vector<std::string>& keys,
                 const std::string& expected) {
  const Json& v = at(j, file, keys, expected);
  if (!v.is_number()) throw InputError(file, joined(keys), "expected " + expected);
  return v.get<double>();
}

std::string text_at(const Json& j, const std::string& file, const std::vector<std::string>& keys,
                    const std::string& expected) {
  const Json& v = at(j, file, keys, expected);
  if (!v.is_string()) throw InputError(file, joined(keys), "expected " + expected);
  return v.get<std::string>();
}

}  // namespace

ArchingRecord read_arching_record(const std::filesystem::path& path, const std::string& against,
                                  const std::string& material, const Hopper& hopper) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw InputError(file, "--arching", "cannot read it: expected a design's results.json");
  Json j;
  try {
    j = Json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file, "--arching",
                     std::string("expected a design's results.json: ") + e.what());
  }
  if (text_at(j, file, {"case", "kind"}, "a hopper design") != "hopper")
    throw InputError(file, "case.kind", "expected a hopper design");
  const std::string made_of =
      text_at(j, file, {"input_display", "material.name"}, "the material's name");
  if (made_of != material)
    throw InputError(file, "input_display.material.name",
                     "expected the calibrated material " + material + ", got " + made_of);
  const std::string shape = text_at(j, file, {"inputs", "hopper", "shape"}, "wedge or conical");
  if (shape != hopper.shape)
    throw InputError(file, "inputs.hopper.shape",
                     "expected the case's " + hopper.shape + ", got " + shape);

  const std::string width = "results.critical_outlet_width";
  const std::string rung =
      text_at(j, file, {"results", "critical_outlet_width", "rung"}, "the rung that verified B_c");
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
      number_at(j, file, {"inputs", "hopper", "semi_angle"}, "the semi-angle [rad]");
  r.observation.hopper.wall_friction_angle = number_at(
      j, file, {"inputs", "hopper", "wall_friction_angle"}, "the wall friction angle [rad]");
  r.observation.arches_at = number_at(j, file, {"results", "critical_outlet_width", "low"},
                                      "the widest outlet that arched [m]");
  r.observation.flows_at = number_at(j, file, {"results", "critical_outlet_width", "high"},
                                     "the narrowest outlet that flowed [m]");
  if (!(r.observation.arches_at > 0.0 && r.observation.arches_at < r.observation.flows_at))
    throw InputError(file, width,
                     "expected a bracket: an outlet that arched below one that flowed");
  const std::string model =
      text_at(j, file, {"results", "critical_outlet_width", "model"}, "the verifying model");
  const std::size_t cut = model.find(" bisection: ");
  r.rung = rung + " " + model.substr(0, cut);
  r.bracket = cut == std::string::npos ? model : model.substr(cut + 12);
  // The bisection's runs lie beside the run the record names (its verification folder).
  std::set<std::filesystem::path> folders;
  if (j.contains("provenance") && j["provenance"].contains("simulation_runs"))
    for (const auto& run : j["provenance"]["simulation_runs"])
      if (run.is_string())
        folders.insert((path.parent_path() / run.get<std::string>()).parent_path());
  for (const auto& folder : folders) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
      std::ifstream run_json(entry.path() / "run.json");
      if (!run_json) continue;
      const Json saved = Json::parse(run_json, nullptr, false);
      if (saved.is_object() && saved.contains("commit") && saved["commit"].is_string())
        r.commits.insert(saved["commit"].get<std::string>());
    }
  }
  return r;
}

}  // namespace feedflow
