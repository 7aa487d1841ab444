#include "designer/design/model_choices.hpp"

#include <algorithm>
#include <vector>

#include "designer/case/did_you_mean.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

constexpr std::string_view kFlowFactor[] = {"enstad", "rsf"};
constexpr std::string_view kCriticalOutlet[] = {"envelope", "jenike", "static_arch"};
constexpr std::string_view kDischarge[] = {"johanson", "beverloo", "brown"};
constexpr std::string_view kBulkDensity[] = {"compressible", "table", "constant"};
constexpr std::string_view kStopping[] = {"pouliquen", "hybrid"};
constexpr std::string_view kDeposit[] = {"l1", "none"};

constexpr ModelOption kOptions[] = {
    {"hopper.flow_factor", "enstad", kFlowFactor,
     "enstad: Enstad/Arnold-McLean closed form; rsf: Jenike's radial stress field (shooting)"},
    {"hopper.critical_outlet", "envelope", kCriticalOutlet,
     "envelope: the larger of Jenike's H(theta) and the static-arch H_a; or either alone"},
    {"hopper.discharge", "johanson", kDischarge,
     "johanson (cohesive, mass flow), beverloo (empirical) or brown (minimum energy, wedge)"},
    {"hopper.bulk_density", "compressible", kBulkDensity,
     "compressible: rho_b at the local stress from the Bauer law (or the material's table when it has no "
     "hypoplastic parameters); table: the measured compressibility table; constant: the design density"},
    {"chute.stopping_thickness", "pouliquen", kStopping,
     "pouliquen: h_stop law; hybrid: Pouliquen plus the low-stress cohesion"},
    {"chute.deposit", "l1", kDeposit,
     "l1: depth-averaged release from the bin (rung L1); none: skip it"},
};

}  // namespace

std::span<const ModelOption> model_options() { return kOptions; }

ModelChoices ModelChoices::parse(std::span<const std::string> settings) {
  ModelChoices c;
  std::vector<std::string_view> keys;
  for (const auto& o : kOptions) keys.push_back(o.key);
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos)
      throw InputError("--model", s, "expected key=name, e.g. --model hopper.flow_factor=rsf");
    const std::string key = s.substr(0, eq), name = s.substr(eq + 1);
    const auto* option = std::find_if(std::begin(kOptions), std::end(kOptions),
                                      [&](const ModelOption& o) { return o.key == key; });
    if (option == std::end(kOptions)) {
      std::string list;
      for (const auto k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
      throw InputError("--model", key, "unknown model key" + did_you_mean(key, keys) + "; known: " + list);
    }
    if (std::find(option->choices.begin(), option->choices.end(), name) == option->choices.end()) {
      std::string list;
      for (const auto n : option->choices) list += (list.empty() ? "" : ", ") + std::string(n);
      throw InputError("--model", key, "unknown model \"" + name + "\"" +
                                           did_you_mean(name, option->choices) + "; choose " + list);
    }
    c.chosen_[key] = name;
  }
  return c;
}

std::string_view ModelChoices::operator[](std::string_view key) const {
  if (const auto it = chosen_.find(key); it != chosen_.end()) return it->second;
  for (const auto& o : kOptions)
    if (o.key == key) return o.default_choice;
  return {};
}

}  // namespace feedflow
