#include "designer/design/model_choices.hpp"

#include <algorithm>
#include <vector>

#include "designer/case/did_you_mean.hpp"
#include "models/chute/deposit_models.hpp"
#include "models/chute/stopping_thickness_models.hpp"
#include "models/core/errors.hpp"
#include "models/hopper/bulk_density_models.hpp"
#include "models/hopper/critical_outlet_models.hpp"
#include "models/hopper/discharge_models.hpp"
#include "models/hopper/flow_factor_models.hpp"

namespace feedflow {
namespace {

std::vector<ModelListing> listings() {
  return {flow_factor_models().listing(),     critical_outlet_models().listing(),
          discharge_models().listing(),       hopper_density_models().listing(),
          stopping_thickness_models().listing(), chute_deposit_models().listing()};
}

std::string joined(const std::vector<std::string_view>& names) {
  std::string list;
  for (const auto n : names) list += (list.empty() ? "" : ", ") + std::string(n);
  return list;
}

}  // namespace

std::span<const ModelListing> model_options() {
  static const std::vector<ModelListing> options = listings();
  return options;
}

ModelChoices ModelChoices::parse(std::span<const std::string> settings) {
  ModelChoices c;
  std::vector<std::string_view> keys;
  for (const auto& o : model_options()) keys.push_back(o.key);
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos)
      throw InputError("--model", s, "expected key=name, e.g. --model hopper.flow_factor=rsf");
    const std::string key = s.substr(0, eq), name = s.substr(eq + 1);
    const auto options = model_options();
    const auto option = std::find_if(options.begin(), options.end(), [&](const ModelListing& o) { return o.key == key; });
    if (option == options.end())
      throw InputError("--model", key, "unknown model key" + did_you_mean(key, keys) + "; known: " + joined(keys));
    std::vector<std::string_view> names;
    for (const auto& e : option->entries) names.push_back(e.name);
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw InputError("--model", key, "unknown model \"" + name + "\"" + did_you_mean(name, names) + "; choose " +
                                           joined(names));
    c.chosen_[key] = name;
  }
  return c;
}

std::string_view ModelChoices::operator[](std::string_view key) const {
  if (const auto it = chosen_.find(key); it != chosen_.end()) return it->second;
  for (const auto& o : model_options())
    if (o.key == key) return o.entries.front().name;
  return {};
}

}  // namespace feedflow
