#include "designer/calibrate/verified_record.hpp"

#include <cmath>
#include <fstream>

#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

using Json = nlohmann::ordered_json;

std::string joined(const std::vector<std::string>& keys) {
  std::string path;
  for (const auto& k : keys) (path += path.empty() ? "" : ".") += k;
  return path;
}

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

}  // namespace

VerifiedRecord VerifiedRecord::read(const std::filesystem::path& file, const std::string& option,
                                    const std::string& kind, const std::string& material) {
  std::ifstream in(file);
  if (!in)
    throw InputError(file.string(), option, "cannot read it: expected a design's results.json");
  VerifiedRecord r;
  r.file = file;
  try {
    r.json = Json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string(), option,
                     std::string("expected a design's results.json: ") + e.what());
  }
  if (r.text({"case", "kind"}, "a " + kind + " design") != kind)
    throw InputError(file.string(), "case.kind", "expected a " + kind + " design");
  const std::string made_of = r.text({"input_display", "material.name"}, "the material's name");
  if (made_of != material)
    throw InputError(file.string(), "input_display.material.name",
                     "expected the calibrated material " + material + ", got " + made_of);
  return r;
}

double VerifiedRecord::number(const std::vector<std::string>& keys,
                              const std::string& expected) const {
  const Json& v = at(json, file.string(), keys, expected);
  if (!v.is_number()) throw InputError(file.string(), joined(keys), "expected " + expected);
  return v.get<double>();
}

std::string VerifiedRecord::text(const std::vector<std::string>& keys,
                                 const std::string& expected) const {
  const Json& v = at(json, file.string(), keys, expected);
  if (!v.is_string()) throw InputError(file.string(), joined(keys), "expected " + expected);
  return v.get<std::string>();
}

std::string VerifiedRecord::dem_law(const std::string& result) const {
  const std::string model = text({"results", result, "model"}, "the verifying model");
  const auto close = model.find(')');
  if (model.rfind("DEM (", 0) != 0 || close == std::string::npos)
    throw InputError(file.string(), "results." + result + ".model",
                     "expected \"DEM (LAW) ...\", got \"" + model + "\"");
  return model.substr(5, close - 5);
}

std::optional<double> VerifiedRecord::sphere_radius() const {
  if (!json.contains(Json::json_pointer("/inputs/material/dem/particle/radius")))
    return std::nullopt;
  return number({"inputs", "material", "dem", "particle", "radius"}, "the spheres' radius [m]");
}

void check_sphere_radius(const std::filesystem::path& file, std::optional<double> was,
                         double radius) {
  if (was && std::abs(*was - radius) > 1e-9 * radius)
    throw InputError(file.string(), "inputs.material.dem.particle.radius",
                     "expected runs of the case's spheres (" + format_quantity(radius, "mm", 4) +
                         " radius), got " + format_quantity(*was, "mm", 4));
}

std::set<std::string> VerifiedRecord::run_commits() const {
  std::set<std::filesystem::path> folders;
  if (json.contains("provenance") && json["provenance"].contains("simulation_runs"))
    for (const auto& run : json["provenance"]["simulation_runs"])
      if (run.is_string())
        folders.insert((file.parent_path() / run.get<std::string>()).parent_path());
  std::set<std::string> commits;
  for (const auto& folder : folders) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
      std::ifstream run_json(entry.path() / "run.json");
      if (!run_json) continue;
      const Json saved = Json::parse(run_json, nullptr, false);
      if (saved.is_object() && saved.contains("commit") && saved["commit"].is_string())
        commits.insert(saved["commit"].get<std::string>());
    }
  }
  return commits;
}

}  // namespace feedflow
