#pragma once
// Alternative models a user can select with `--model key=name` (e.g. hopper.flow_factor=rsf):
// one key per model table (models/hopper, models/chute), one name per row. Every key has a
// default (the table's first row); unknown keys and names are input errors that list the
// choices.
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "models/core/model_table.hpp"

namespace feedflow {

// Every model table's listing, in the order --model help shows them.
std::span<const ModelListing> model_options();

class ModelChoices {
 public:
  // Parses "key=name" settings; throws InputError naming "--model" and the key.
  static ModelChoices parse(std::span<const std::string> settings);
  // Whether --model set `key` (else its row is the default, or what the material's calibration
  // prefers).
  bool is_set(std::string_view key) const { return chosen_.find(key) != chosen_.end(); }
  // The chosen name for a key (the default when not set).
  std::string_view operator[](std::string_view key) const;
  // The chosen row of a table (its default when not set).
  template <class Row>
  const Row& of(const ModelTable<Row>& table) const {
    return table.at((*this)[table.key]);
  }

 private:
  std::map<std::string, std::string, std::less<>> chosen_;
};

}  // namespace feedflow
