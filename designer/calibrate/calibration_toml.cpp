#include "designer/calibrate/calibration_toml.hpp"

#include <charconv>
#include <sstream>

#include "designer/case/material_text.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

// A TOML basic string.
std::string toml_string(std::string_view s) {
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

// "figures = { name = "text", ... }" and a newline; nothing without figures.
void write_figures(std::ostream& o, const std::map<std::string, std::string>& figures) {
  if (figures.empty()) return;
  o << "figures = {";
  bool first = true;
  for (const auto& [name, text] : figures) {
    o << (first ? " " : ", ") << name << " = " << toml_string(text);
    first = false;
  }
  o << " }\n";
}

}  // namespace

std::string calibration_toml(const Calibration& c, const std::vector<CalibrationPointRecord>& points) {
  std::ostringstream o;
  o << "# Written by `feedflow calibrate`: reduced-model coefficients fitted to a full rung. The design\n"
       "# check uses them for " << c.geometry << " hoppers with hopper.bulk_density=" << c.density_model << ".\n";
  o << "[calibration]\n";
  o << "against = " << toml_string(c.against) << "\n";
  o << "rung = " << toml_string(c.rung) << "\n";
  o << "scene = " << toml_string(c.scene) << "\n";
  o << "geometry = " << toml_string(c.geometry) << "\n";
  o << "density_model = " << toml_string(c.density_model) << "\n";
  o << "commit = " << toml_string(c.commit) << "\n";
  o << "date = " << toml_string(c.date) << "\n";
  for (const auto& [row, model] : c.discharge) {
    o << "\n[calibration.discharge." << row << "]\n";
    o << "coefficients = {";
    bool first = true;
    for (const auto& [name, value] : model.coefficients) {
      o << (first ? " " : ", ") << name << " = " << number(value);
      first = false;
    }
    o << " }\n";
    write_figures(o, model.figures);
  }
  for (const auto& p : points) {
    o << "\n[[calibration.points]]\n";
    o << "outlet_width = " << toml_string(format_number(p.outlet_width * 1e3, 6) + " mm") << "\n";
    o << "semi_angle = " << toml_string(format_number(in_degrees(p.semi_angle), 6) + " deg")
      << "\n";
    o << "mass_flow_rate = " << toml_string(format_number(p.reference, 6) + " kg/s") << "\n";
    o << "error_bar = " << toml_string(format_number(p.error_bar, 4) + " kg/s") << "\n";
    o << "held_out = " << (p.held_out ? "true" : "false") << "\n";
    o << "source = " << toml_string(p.source) << "\n";
  }
  return o.str();
}

std::string arching_calibration_toml(const ArchingCalibration& c,
                                     const std::vector<ArchingPointRecord>& points) {
  std::ostringstream o;
  o << "# Written by `feedflow calibrate --arching`: the flow function's strength in the arching "
       "models\n"
       "# fitted to a full rung's critical outlet widths. The design check uses it for "
    << c.geometry << " hoppers with\n# hopper.flow_factor=" << c.flow_factor << ".\n";
  o << "[calibration.arching]\n";
  o << "against = " << toml_string(c.against) << "\n";
  o << "rung = " << toml_string(c.rung) << "\n";
  o << "scene = " << toml_string(c.scene) << "\n";
  o << "geometry = " << toml_string(c.geometry) << "\n";
  o << "flow_factor = " << toml_string(c.flow_factor) << "\n";
  o << "commit = " << toml_string(c.commit) << "\n";
  o << "date = " << toml_string(c.date) << "\n";
  for (const auto& [row, model] : c.rows) {
    o << "\n[calibration.arching.rows." << row << "]\n";
    o << "coefficients = { strength_scale = " << number(model.coefficients.at("strength_scale"))
      << " }\n";
    write_figures(o, model.figures);
  }
  for (const auto& p : points) {
    o << "\n[[calibration.arching.points]]\n";
    o << "semi_angle = " << toml_string(format_number(in_degrees(p.semi_angle), 6) + " deg")
      << "\n";
    o << "wall_friction_angle = "
      << toml_string(format_number(in_degrees(p.wall_friction_angle), 6) + " deg") << "\n";
    o << "arches_at = " << toml_string(format_number(p.arches_at * 1e3, 6) + " mm") << "\n";
    o << "flows_at = " << toml_string(format_number(p.flows_at * 1e3, 6) + " mm") << "\n";
    o << "held_out = " << (p.held_out ? "true" : "false") << "\n";
    o << "source = " << toml_string(p.source) << "\n";
  }
  return o.str();
}

std::string drum_calibration_toml(const DrumCalibration& c,
                                  const std::vector<DrumPointRecord>& points) {
  std::ostringstream o;
  o << "# Written by `feedflow calibrate`: the drum's flowing layer fitted to a full rung over "
       "drum speeds.\n";
  o << "[calibration.drum]\n";
  o << "against = " << toml_string(c.against) << "\n";
  o << "rung = " << toml_string(c.rung) << "\n";
  o << "scene = " << toml_string(c.scene) << "\n";
  o << "end_walls = " << (c.end_walls ? "true" : "false") << "\n";
  if (c.diameter)
    o << "diameter = " << toml_string(format_number(*c.diameter * 1e3, 6) + " mm") << "\n";
  if (c.fill_fraction) o << "fill_fraction = " << number(*c.fill_fraction) << "\n";
  o << "commit = " << toml_string(c.commit) << "\n";
  o << "date = " << toml_string(c.date) << "\n";
  o << "coefficients = { layer_fraction = " << number(c.layer.coefficients.at("layer_fraction"))
    << ", friction_shift = "
    << toml_string(number(in_degrees(c.layer.coefficients.at("friction_shift"))) + " deg")
    << " }\n";
  write_figures(o, c.layer.figures);
  for (const auto& p : points) {
    o << "\n[[calibration.drum.points]]\n";
    o << "speed = " << toml_string(format_number(in_rpm(p.speed), 6) + " rpm") << "\n";
    o << "dynamic_angle_of_repose = "
      << toml_string(format_number(in_degrees(p.reference), 6) + " deg") << "\n";
    o << "error_bar = " << toml_string(format_number(in_degrees(p.error_bar), 4) + " deg") << "\n";
    o << "held_out = " << (p.held_out ? "true" : "false") << "\n";
    o << "source = " << toml_string(p.source) << "\n";
  }
  return o.str();
}

std::string chute_calibration_toml(const ChuteCalibration& c,
                                   const std::vector<ChutePointRecord>& points) {
  std::ostringstream o;
  o << "# Written by `feedflow calibrate`: Pouliquen's h_stop law fitted to a full rung's deposits "
       "over the\n# inclination of a plane. The chute check uses it; the drum's flowing layer "
       "keeps [surface_flow].\n";
  o << "[calibration.chute]\n";
  o << "against = " << toml_string(c.against) << "\n";
  o << "rung = " << toml_string(c.rung) << "\n";
  o << "scene = " << toml_string(c.scene) << "\n";
  o << "lowest_angle = " << toml_string(number(in_degrees(c.lowest_angle)) + " deg") << "\n";
  o << "highest_angle = " << toml_string(number(in_degrees(c.highest_angle)) + " deg") << "\n";
  o << "commit = " << toml_string(c.commit) << "\n";
  o << "date = " << toml_string(c.date) << "\n";
  o << "coefficients = { ";
  if (const auto t1 = c.law.coefficients.find("theta1"); t1 != c.law.coefficients.end())
    o << "theta1 = " << toml_string(number(in_degrees(t1->second)) + " deg") << ", ";
  o << "theta2 = " << toml_string(number(in_degrees(c.law.coefficients.at("theta2"))) + " deg")
    << ", stop_length = " << toml_string(number(c.law.coefficients.at("stop_length") * 1e3) + " mm")
    << " }\n";
  write_figures(o, c.law.figures);
  for (const auto& p : points) {
    o << "\n[[calibration.chute.points]]\n";
    o << "angle = " << toml_string(format_number(in_degrees(p.angle), 6) + " deg") << "\n";
    o << "deposit_thickness = " << toml_string(format_number(p.reference * 1e3, 6) + " mm") << "\n";
    o << "error_bar = " << toml_string(format_number(p.error_bar * 1e3, 4) + " mm") << "\n";
    o << "held_out = " << (p.held_out ? "true" : "false") << "\n";
    o << "source = " << toml_string(p.source) << "\n";
  }
  return o.str();
}

std::string with_calibration(std::string_view text, std::string_view table, CalibrationPart part) {
  const std::string kept = without_calibration(text, part);
  return kept + (kept.empty() ? "" : "\n") + std::string(table);
}

}  // namespace feedflow
