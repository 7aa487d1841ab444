#include "models/units/quantity_list.hpp"

#include <cctype>
#include <stdexcept>
#include <string>

#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// The unit after the number of an item ("100 mm" -> "mm"; "100" -> "").
std::string_view unit_of(std::string_view item) {
  std::size_t k = 0;
  while (k < item.size() && (std::isdigit(static_cast<unsigned char>(item[k])) || item[k] == '.' || item[k] == '-' ||
                             item[k] == '+' || ((item[k] == 'e' || item[k] == 'E') && k > 0 && k + 1 < item.size() &&
                                                (std::isdigit(static_cast<unsigned char>(item[k + 1])) || item[k + 1] == '-'))))
    ++k;
  return trimmed(item.substr(k));
}

}  // namespace

std::vector<double> parse_quantity_list(std::string_view text, const Dimension& expected) {
  std::vector<std::string_view> items;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    items.push_back(trimmed(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  std::string_view shared_unit;
  for (const auto item : items) {
    if (item.empty()) throw std::invalid_argument("an empty item in \"" + std::string(text) + "\"");
    if (!unit_of(item).empty()) shared_unit = unit_of(item);
  }
  std::vector<double> values;
  for (const auto item : items) {
    std::string typed(item);
    if (unit_of(item).empty()) {
      if (shared_unit.empty() && expected != dim::dimensionless)
        throw std::invalid_argument("\"" + std::string(text) + "\" has no unit; expected " + dimension_name(expected) +
                                    ", e.g. " + example_value(expected));
      typed += " " + std::string(shared_unit);
    }
    values.push_back(parse_quantity_as(trimmed(typed), expected, false));
  }
  return values;
}

}  // namespace feedflow
