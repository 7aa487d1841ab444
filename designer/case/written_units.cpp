#include "designer/case/written_units.hpp"

#include <cstdlib>

#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

void collect(const toml::table& table, const std::string& prefix,
             std::map<std::string, std::string>& out) {
  for (auto&& [k, node] : table) {
    const std::string key =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    const toml::node* value = &node;
    if (const auto* t = node.as_table()) {
      if (const auto* v = t->get("value")) {
        value = v;  // a value record
      } else {
        collect(*t, key, out);
        continue;
      }
    }
    if (const auto* text = value->as_string())
      if (const std::string unit = unit_written(text->get()); !unit.empty()) out[key] = unit;
  }
}

}  // namespace

std::string unit_written(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  std::strtod(begin, &end);
  if (end == begin) return "";
  std::string unit(end);
  unit.erase(0, unit.find_first_not_of(" \t"));
  unit.erase(unit.find_last_not_of(" \t") + 1);
  if (unit.empty()) return "";
  try {
    parse_unit(unit);
  } catch (const UnitError&) {
    return "";
  }
  return unit;
}

std::map<std::string, std::string> written_units(const toml::table& root) {
  std::map<std::string, std::string> out;
  collect(root, "", out);
  return out;
}

}  // namespace feedflow
