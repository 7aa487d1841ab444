#pragma once
// Alternative models a user can select with `--model key=name` (e.g. hopper.flow_factor=rsf).
// Every key has a default; unknown keys and names are input errors that list the choices.
#include <map>
#include <span>
#include <string>
#include <string_view>

namespace feedflow {

struct ModelOption {
  std::string_view key;                 // "hopper.flow_factor"
  std::string_view default_choice;      // "enstad"
  std::span<const std::string_view> choices;
  std::string_view description;
};

std::span<const ModelOption> model_options();

class ModelChoices {
 public:
  // Parses "key=name" settings; throws InputError naming "--model" and the key.
  static ModelChoices parse(std::span<const std::string> settings);
  // The chosen name for a key (the default when not set).
  std::string_view operator[](std::string_view key) const;

 private:
  std::map<std::string, std::string, std::less<>> chosen_;
};

}  // namespace feedflow
