#include "designer/simulate/restart_identity.hpp"

#include <algorithm>
#include <string_view>

#include "designer/design/case_inputs.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

constexpr const char* kGroup = "/scene/case";

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

bool changes_the_physics(std::string_view key, Solver solver) {
  const bool dem = solver == Solver::dem;
  if (starts_with(key, "design.")) return false;
  if (key.ends_with(".end_time") || key.ends_with(".snapshot_interval")) return false;
  if (starts_with(key, dem ? "cel." : "dem.")) return false;
  if (starts_with(key, "material.")) {
    const std::string_view part = key.substr(std::string_view("material.").size());
    return starts_with(part, "bulk.") || starts_with(part, dem ? "dem." : "hypoplastic.");
  }
  return true;
}

std::string as_text(const InputValue& v) { return v.display.empty() ? std::string("(none)") : v.display; }

}  // namespace

std::vector<InputValue> restart_identity(const Case& c, Solver solver) {
  std::vector<InputValue> all = case_inputs(c);
  for (auto& v : simulation_inputs(c)) all.push_back(std::move(v));
  std::vector<InputValue> out;
  for (auto& v : all)
    if (changes_the_physics(v.key, solver) && !std::holds_alternative<std::vector<double>>(v.value))
      out.push_back(std::move(v));
  return out;
}

void save_restart_identity(const std::vector<InputValue>& identity, Hdf5File& f) {
  f.create_group(kGroup);
  std::string keys;
  for (const auto& v : identity) {
    (keys += keys.empty() ? "" : "\n") += v.key;
    if (const double* x = std::get_if<double>(&v.value)) f.set_attribute(kGroup, v.key, *x);
    else f.set_attribute(kGroup, v.key, std::get<std::string>(v.value));
    f.set_attribute(kGroup, v.key + " as given", as_text(v));
  }
  f.set_attribute(kGroup, "keys", keys);
}

void check_restart_identity(const std::vector<InputValue>& identity, const Hdf5File& f) {
  if (!f.exists(kGroup))
    throw InputError("--restart", "", f.path().string() + " does not say which case it was written for (damaged, a "
                                                          "checkpoint of another program or an older feedflow)");
  std::vector<std::string> saved;
  const std::string keys = f.string_attribute(kGroup, "keys");
  for (std::size_t a = 0; a <= keys.size();) {
    const std::size_t b = std::min(keys.find('\n', a), keys.size());
    if (b > a) saved.emplace_back(keys.substr(a, b - a));
    a = b + 1;
  }
  const auto written_with = [&](const std::string& key) {
    return std::find(saved.begin(), saved.end(), key) != saved.end() ? f.string_attribute(kGroup, key + " as given")
                                                                      : std::string("(none)");
  };
  for (const auto& v : identity) {
    const bool there = std::find(saved.begin(), saved.end(), v.key) != saved.end();
    bool same = there;
    if (there) {
      if (const double* x = std::get_if<double>(&v.value)) same = f.double_attribute(kGroup, v.key) == *x;
      else same = f.string_attribute(kGroup, v.key) == std::get<std::string>(v.value);
    }
    if (!same)
      throw InputError("--restart", v.key, "the checkpoint was written with " + written_with(v.key) +
                                               "; this run gives " + as_text(v) +
                                               " (restart with the case and --set values of the run that wrote it)");
  }
  for (const auto& key : saved) {
    const bool here = std::any_of(identity.begin(), identity.end(), [&](const InputValue& v) { return v.key == key; });
    if (!here)
      throw InputError("--restart", key, "the checkpoint was written with " + written_with(key) +
                                             "; this run does not set it (restart with the case and --set values of "
                                             "the run that wrote it)");
  }
}

}  // namespace feedflow
