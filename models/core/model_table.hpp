#pragma once
// A model table: the alternative models of one quantity, one row each (name, rung, one-line
// summary, evaluate). `--model key=name` picks a row; the help, the bands over the alternatives
// and the charts loop over the rows. A row's name is compared nowhere but here: adding a model
// is one evaluate function and one row.
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "models/core/estimate.hpp"

namespace feedflow {

// What every row says of itself.
struct ModelEntry {
  std::string_view name;     // what --model takes: "beverloo"
  Rung rung = Rung::L0;      // the rung the model stands on
  std::string_view summary;  // one line, for --model help and the report
};

// The common row: an entry and its evaluate function (a function pointer, so tables are
// constant data). Tables whose rows carry more (a chart legend, band membership) define
// their own row type deriving from ModelEntry.
template <class Evaluate>
struct ModelRow : ModelEntry {
  Evaluate evaluate;
};

// The listing of a table for the command line: its key, its rows' entries (the first is the
// default) and what the key chooses.
struct ModelListing {
  std::string_view key;
  std::string_view description;
  std::vector<ModelEntry> entries;
};

template <class Row>
struct ModelTable {
  std::string_view key;          // "hopper.discharge"
  std::string_view description;  // what the key chooses: "discharge rate"
  std::span<const Row> rows;     // the first row is the default

  const Row& default_row() const { return rows.front(); }
  // The row named `name`; null when the table has none.
  const Row* find(std::string_view name) const {
    for (const Row& r : rows)
      if (r.name == name) return &r;
    return nullptr;
  }
  // The row named `name`; throws std::out_of_range naming the key (parse --model first).
  const Row& at(std::string_view name) const {
    if (const Row* r = find(name)) return *r;
    throw std::out_of_range(std::string(key) + " has no model \"" + std::string(name) + "\"");
  }
  ModelListing listing() const {
    ModelListing l{key, description, {}};
    for (const Row& r : rows) l.entries.push_back(static_cast<const ModelEntry&>(r));
    return l;
  }
};

}  // namespace feedflow
