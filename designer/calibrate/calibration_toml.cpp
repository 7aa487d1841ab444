#include "designer/calibrate/calibration_toml.hpp"

#include <charconv>
#include <sstream>

#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

// A TOML basic string.
std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// The shortest text that reads back as the same double ("1.83", "1.2345678", "1e-05": valid TOML).
std::string number(double x) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, x).ptr;
  return std::string(text, end);
}

// Whether a line opens a table whose name starts with "calibration" ("[calibration]",
// "[calibration.discharge.beverloo]", "[[calibration.points]]").
bool calibration_header(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos || line[first] != '[') return false;
  std::string_view rest = line.substr(first);
  while (!rest.empty() && (rest.front() == '[' || rest.front() == ' ')) rest.remove_prefix(1);
  return rest.substr(0, 11) == "calibration" && (rest.size() == 11 || rest[11] == '.' || rest[11] == ']' || rest[11] == ' ');
}

bool any_header(std::string_view line) {
  const auto first = line.find_first_not_of(" \t");
  return first != std::string_view::npos && line[first] == '[';
}

}  // namespace

std::string calibration_toml(const Calibration& c, const std::vector<CalibrationPointRecord>& points) {
  std::ostringstream o;
  o << "# Written by `feedflow calibrate`: reduced-model coefficients fitted to a full rung. The design\n"
       "# check uses them for " << c.geometry << " hoppers with hopper.bulk_density=" << c.density_model << ".\n";
  o << "[calibration]\n";
  o << "against = " << quoted(c.against) << "\n";
  o << "rung = " << quoted(c.rung) << "\n";
  o << "scene = " << quoted(c.scene) << "\n";
  o << "geometry = " << quoted(c.geometry) << "\n";
  o << "density_model = " << quoted(c.density_model) << "\n";
  o << "commit = " << quoted(c.commit) << "\n";
  o << "date = " << quoted(c.date) << "\n";
  for (const auto& [row, model] : c.discharge) {
    o << "\n[calibration.discharge." << row << "]\n";
    o << "coefficients = {";
    bool first = true;
    for (const auto& [name, value] : model.coefficients) {
      o << (first ? " " : ", ") << name << " = " << number(value);
      first = false;
    }
    o << " }\n";
    if (!model.figures.empty()) {
      o << "figures = {";
      first = true;
      for (const auto& [name, text] : model.figures) {
        o << (first ? " " : ", ") << name << " = " << quoted(text);
        first = false;
      }
      o << " }\n";
    }
  }
  for (const auto& p : points) {
    o << "\n[[calibration.points]]\n";
    o << "outlet_width = " << quoted(format_number(p.outlet_width * 1e3, 6) + " mm") << "\n";
    o << "semi_angle = " << quoted(format_number(in_degrees(p.semi_angle), 6) + " deg") << "\n";
    o << "mass_flow_rate = " << quoted(format_number(p.reference, 6) + " kg/s") << "\n";
    o << "error_bar = " << quoted(format_number(p.error_bar, 4) + " kg/s") << "\n";
    o << "held_out = " << (p.held_out ? "true" : "false") << "\n";
    o << "source = " << quoted(p.source) << "\n";
  }
  return o.str();
}

std::string with_calibration(std::string_view text, std::string_view table) {
  std::string kept;
  bool inside = false;
  std::string pending_comments;  // comment lines just above a header belong to that header
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    const std::string_view line = text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
    pos = end == std::string_view::npos ? text.size() : end + 1;
    const auto first = line.find_first_not_of(" \t");
    const bool comment = first != std::string_view::npos && line[first] == '#';
    if (comment) {
      pending_comments += std::string(line) + "\n";
      continue;
    }
    if (any_header(line)) inside = calibration_header(line);
    if (!inside) kept += pending_comments + std::string(line) + "\n";
    pending_comments.clear();
  }
  if (!inside) kept += pending_comments;
  while (kept.size() >= 2 && kept[kept.size() - 1] == '\n' && kept[kept.size() - 2] == '\n') kept.pop_back();
  if (!kept.empty() && kept.back() != '\n') kept += '\n';
  return kept + "\n" + std::string(table);
}

}  // namespace feedflow
