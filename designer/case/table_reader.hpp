#pragma once
// Reads one TOML table into a record described by a FieldSpec table (models/core/field_spec.hpp):
// units, dimensions, ranges, label choices, unknown keys with suggestions. Every error is an
// InputError naming the file and line (or "--set") and the dotted key.
#include <cmath>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <vector>

#include "models/core/errors.hpp"
#include "models/core/field_spec.hpp"

namespace feedflow {

struct TableContext {
  std::string prefix;          // dotted path of the table: "hopper", "material.bulk"
  std::string file;            // file the table came from, for errors without a line
  bool overriding = false;     // true: a layer over values already set, nothing is required
  std::map<std::string, std::string>* sources = nullptr;  // dotted key -> "source" given
  std::vector<std::string>* keys_given = nullptr;         // keys present in the table

  std::string dotted(std::string_view key) const {
    return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
  }
};

// "file:line" of a node, or "--set" for a value given on the command line.
std::string location(const toml::node& node, const std::string& file);

// A plain value or the `value` of a value record `{ value = ..., source = "..." }`; records the
// source in ctx.sources.
const toml::node& value_of(const toml::node& node, const std::string& key, const TableContext& ctx);

double read_quantity(const toml::node& node, const Dimension& dimension, const std::string& key,
                     const TableContext& ctx);
std::string read_text(const toml::node& node, const std::string& key, const TableContext& ctx);

// Throws the "unknown key" error if `key` is not among `known`.
void require_known_key(const toml::node& node, std::string_view key,
                       std::span<const std::string_view> known, const TableContext& ctx);

// Throws when the table is missing; where names the table's parent.
[[noreturn]] void missing_key(const toml::node& parent, const std::string& dotted_key,
                              const std::string& what, const std::string& file);

// Formats a value for an error message in the field's unit.
std::string format_for_error(double si, std::string_view unit);

template <class Record>
void read_fields(const toml::table& table, std::span<const FieldSpec<Record>> fields,
                 Record& record, const TableContext& ctx,
                 std::span<const std::string_view> other_keys = {}) {
  std::vector<std::string_view> known(other_keys.begin(), other_keys.end());
  for (const auto& f : fields) known.push_back(f.key);
  for (auto&& [k, node] : table) {
    require_known_key(node, k.str(), known, ctx);
    if (ctx.keys_given) ctx.keys_given->push_back(std::string(k.str()));
  }
  for (const auto& f : fields) {
    const toml::node* node = table.get(f.key);
    const std::string key = ctx.dotted(f.key);
    if (!node) {
      if (f.presence == Presence::required && !ctx.overriding)
        missing_key(table, key,
                    f.is_label() ? "one of the allowed words" : std::string(f.description),
                    ctx.file);
      continue;
    }
    const toml::node& value = value_of(*node, key, ctx);
    if (f.is_label()) {
      std::string text = read_text(value, key, ctx);
      bool allowed = false;
      std::string list;
      for (const auto c : f.choices) {
        allowed = allowed || c == text;
        list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
      }
      if (!allowed)
        throw InputError(location(value, ctx.file), key,
                         "expected one of " + list + ", got \"" + text + "\"");
      record.*(f.label) = std::move(text);
      continue;
    }
    if (f.number_list) {
      const auto* array = value.as_array();
      if (!array)
        throw InputError(location(value, ctx.file), key,
                         "expected a list of values, e.g. [\"0.1 kPa\", \"1 kPa\"]");
      std::vector<double> list;
      for (const auto& item : *array) {
        list.push_back(read_quantity(item, f.dimension, key, ctx));
        if (!f.range.contains(list.back()))
          throw InputError(location(item, ctx.file), key,
                           "out of range: " + f.range.describe(f.display_unit) + ", got " +
                               format_for_error(list.back(), f.display_unit));
      }
      record.*(f.number_list) = std::move(list);
      continue;
    }
    const double si = read_quantity(value, f.dimension, key, ctx);
    if (!f.range.contains(si))  // the description says what the key is, and so why the range
      throw InputError(location(value, ctx.file), key,
                       "out of range: " + f.range.describe(f.display_unit) + ", got " +
                           format_for_error(si, f.display_unit) + " (" + std::string(f.description) + ")");
    if (f.whole && si != std::floor(si))
      throw InputError(location(value, ctx.file), key,
                       "expected a whole number, got " + format_for_error(si, f.display_unit));
    if (f.number)
      record.*(f.number) = si;
    else
      record.*(f.optional_number) = si;
  }
}

// Turns the problems of a cross-field check into an InputError (the first error) and collects
// the warnings.
void raise_problems(const std::vector<FieldProblem>& problems, const toml::table& table,
                    const TableContext& ctx, std::vector<std::string>* warnings);

}  // namespace feedflow
