#include "designer/case/material_text.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "models/material/builtin_materials.hpp"

namespace feedflow {
namespace {

// The table name a header line opens, from its first letter ("calibration.drum]").
std::string_view header_name(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos || line[first] != '[') return {};
  std::string_view rest = line.substr(first);
  while (!rest.empty() && (rest.front() == '[' || rest.front() == ' ')) rest.remove_prefix(1);
  return rest;
}

// Whether `name` is the table `table` or one under it ("calibration.drum.points" is under
// "calibration.drum").
bool names(std::string_view name, std::string_view table) {
  const std::size_t n = table.size();
  return name.substr(0, n) == table &&
         (name.size() == n || name[n] == '.' || name[n] == ']' || name[n] == ' ');
}

// Whether a line opens a table of `part` of the material's calibration.
bool calibration_header(std::string_view line, CalibrationPart part) {
  const std::string_view name = header_name(line);
  if (!names(name, "calibration")) return false;
  if (part == CalibrationPart::all) return true;
  const CalibrationPart own = names(name, "calibration.drum")      ? CalibrationPart::drum
                              : names(name, "calibration.arching") ? CalibrationPart::arching
                              : names(name, "calibration.chute")   ? CalibrationPart::chute
                                                                   : CalibrationPart::hopper;
  return own == part;
}

bool any_header(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  return first != std::string_view::npos && line[first] == '[';
}

}  // namespace

std::string material_text(const Material& m) {
  if (m.origin != "built-in" && std::filesystem::is_regular_file(m.origin)) {
    std::ifstream in(m.origin);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  if (m.origin == "built-in")
    for (const auto& b : builtin_material_texts())
      if (b.name == m.name) return std::string(b.toml);
  return {};
}

std::string without_calibration(std::string_view text, CalibrationPart part) {
  std::string kept;
  bool inside = false;
  std::string pending_comments;  // comment lines just above a header belong to that header
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    const std::string_view line = text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
    pos = end == std::string_view::npos ? text.size() : end + 1;
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string_view::npos && line[first] == '#') {
      pending_comments += std::string(line) + "\n";
      continue;
    }
    if (any_header(line)) inside = calibration_header(line, part);
    if (!inside) kept += pending_comments + std::string(line) + "\n";
    pending_comments.clear();
  }
  if (!inside) kept += pending_comments;
  while (!kept.empty() && (kept.back() == '\n' || kept.back() == ' ')) kept.pop_back();
  return kept.empty() ? kept : kept + "\n";
}

}  // namespace feedflow
