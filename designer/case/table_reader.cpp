#include "designer/case/table_reader.hpp"

#include <cmath>

#include "designer/case/did_you_mean.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {

std::string location(const toml::node& node, const std::string& file) {
  const auto& src = node.source();
  if (src.begin.line == 0) return "--set";
  const std::string path = src.path ? *src.path : file;
  return path + ":" + std::to_string(src.begin.line);
}

const toml::node& value_of(const toml::node& node, const std::string& key,
                           const TableContext& ctx) {
  const auto* record = node.as_table();
  if (!record) return node;
  static constexpr std::string_view kRecordKeys[] = {"value", "source", "note"};
  for (auto&& [k, v] : *record) {
    if (k.str() != "value" && k.str() != "source" && k.str() != "note")
      throw InputError(location(v, ctx.file), key + "." + std::string(k.str()),
                       "unknown key in a value record; a value record holds only value, "
                       "source and note" +
                           did_you_mean(k.str(), kRecordKeys));
  }
  const toml::node* value = record->get("value");
  if (!value)
    throw InputError(location(node, ctx.file), key,
                     "a table here must be a value record { value = ..., source = \"...\" }; "
                     "it has no value");
  if (const auto* source = record->get("source")) {
    if (!source->is_string())
      throw InputError(location(*source, ctx.file), key + ".source", "expected a string");
    if (ctx.sources) (*ctx.sources)[key] = source->as_string()->get();
  }
  return *value;
}

double read_quantity(const toml::node& node, const Dimension& dimension, const std::string& key,
                     const TableContext& ctx) {
  const std::string where = location(node, ctx.file);
  if (node.is_integer()) return static_cast<double>(node.as_integer()->get());
  if (node.is_floating_point()) {
    const double v = node.as_floating_point()->get();
    if (!std::isfinite(v)) throw InputError(where, key, "expected a finite number, got " + format_number(v));
    return v;
  }
  if (node.is_string()) {
    try {
      return parse_quantity_as(node.as_string()->get(), dimension);
    } catch (const UnitError& e) {
      throw InputError(where, key, e.what());
    }
  }
  throw InputError(where, key,
                   "expected a number in SI units or a string with a unit for this " +
                       dimension_name(dimension) + " (e.g. " + example_value(dimension) + ")");
}

std::string read_text(const toml::node& node, const std::string& key, const TableContext& ctx) {
  if (!node.is_string())
    throw InputError(location(node, ctx.file), key, "expected a string in double quotes");
  return node.as_string()->get();
}

void require_known_key(const toml::node& node, std::string_view key,
                       std::span<const std::string_view> known, const TableContext& ctx) {
  for (const auto k : known)
    if (k == key) return;
  std::string list;
  for (const auto k : known) list += (list.empty() ? "" : ", ") + std::string(k);
  throw InputError(location(node, ctx.file), ctx.dotted(key),
                   "unknown key" + did_you_mean(key, known) + "; " +
                       (ctx.prefix.empty() ? std::string("the file accepts")
                                           : "[" + ctx.prefix + "] accepts") +
                       ": " + list);
}

void missing_key(const toml::node& parent, const std::string& dotted_key, const std::string& what,
                 const std::string& file) {
  const auto& src = parent.source();
  const std::string where = src.begin.line == 0 ? file : location(parent, file);
  throw InputError(where, dotted_key, "missing; expected " + what);
}

std::string format_for_error(double si, std::string_view unit) {
  return format_quantity(si, unit, 6);
}

void raise_problems(const std::vector<FieldProblem>& problems, const toml::table& table,
                    const TableContext& ctx, std::vector<std::string>* warnings) {
  for (const auto& p : problems) {
    const toml::node* node = table.get(p.key);
    const std::string where = node ? location(*node, ctx.file)
                              : table.source().begin.line ? location(table, ctx.file)
                                                          : ctx.file;
    if (p.is_error) throw InputError(where, ctx.dotted(p.key), p.message);
    if (warnings) warnings->push_back(where + ": " + ctx.dotted(p.key) + " " + p.message);
  }
}

}  // namespace feedflow
