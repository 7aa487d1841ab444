#pragma once
// A verified design's record (results.json of `feedflow design --verify ...`, or of a sweep point)
// as a calibration reads it: its fields by path, each missing or mistyped one an InputError naming
// the file and the path, and the commits of the programs that made its verification's runs.
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace feedflow {

// InputError naming `file` and inputs.material.dem.particle.radius when a record's spheres
// (`was`, none when it leaves them out) are not `radius` [m]: runs of other spheres answer another
// question.
void check_sphere_radius(const std::filesystem::path& file, std::optional<double> was,
                         double radius);

struct VerifiedRecord {
  std::filesystem::path file;
  nlohmann::ordered_json json;

  // Reads and parses `file` (`option` names the flag that gave it), a design of equipment `kind`
  // ("hopper", "chute") made of `material` (its name); InputError otherwise.
  static VerifiedRecord read(const std::filesystem::path& file, const std::string& option,
                             const std::string& kind, const std::string& material);

  // The value at `keys` (a key may hold a dot: "material.name"); `expected` says what it should be.
  double number(const std::vector<std::string>& keys, const std::string& expected) const;
  std::string text(const std::vector<std::string>& keys, const std::string& expected) const;
  // The DEM law that results.<result>.model names ("DEM (LAW) ..."); InputError otherwise.
  std::string dem_law(const std::string& result) const;
  // [m] the radius of the spheres its runs were made of (inputs.material.dem.particle.radius),
  // none when the record leaves it out (one trimmed to its answers).
  std::optional<double> sphere_radius() const;

  // The commits (read from each run.json) of the runs its provenance names, and of the runs beside
  // them (a bisection's runs share its verification folder).
  std::set<std::string> run_commits() const;
};

}  // namespace feedflow
