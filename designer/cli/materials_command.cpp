// feedflow materials [name]: the materials feedflow knows, or every parameter of one of them.
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "designer/case/material_library.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/design/case_inputs.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

struct MaterialsArguments {
  std::string name;
  CommandOptions options;
};

void list_materials(const MaterialLibrary& library, const CommandOptions& options) {
  const auto entries = library.list();
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& e : entries)
    j.push_back({{"name", e.name}, {"origin", e.origin}, {"description", e.description}});
  write_json_copy(j.dump(2) + "\n", options);
  if (!options.human_output()) return;
  std::printf("%-20s %-44s %s\n", "NAME", "ORIGIN", "DESCRIPTION");
  for (const auto& e : entries)
    std::printf("%-20s %-44s %s\n", e.name.c_str(), e.origin.c_str(), e.description.c_str());
}

std::string figures_text(const CalibratedModel& m) {
  std::string out;
  for (const auto& [name, text] : m.figures)
    if (name.find("_before") == std::string::npos)
      out += (out.empty() ? "" : ", ") + name + " " + text;
  return out;
}

// What `feedflow calibrate` fitted into the material, a line per part (none: not calibrated).
std::vector<std::string> calibration_lines(const Calibration& c) {
  std::vector<std::string> lines;
  if (!c.discharge.empty()) {
    std::string rows;
    for (const auto& [row, model] : c.discharge) {
      std::string coefficients;
      for (const auto& [name, value] : model.coefficients)
        coefficients += (coefficients.empty() ? "" : ", ") + name + " " + format_number(value, 4);
      rows += "\n    " + row + ": " + coefficients + " (" + figures_text(model) + ")";
    }
    lines.push_back("[calibration] hopper discharge, " + c.geometry + " hoppers, against " +
                    c.rung + " over " + std::to_string(c.points) + " points of " + c.scene +
                    " (commit " + c.commit + ", " + c.date + "):" + rows);
  }
  if (const auto& d = c.drum)
    lines.push_back(
        "[calibration.drum] flowing layer: c_delta " +
        format_number(d->layer.coefficients.at("layer_fraction"), 3) + ", friction shift " +
        format_quantity(d->layer.coefficients.at("friction_shift"), "deg", 3) + ", against " +
        d->rung + " over " + std::to_string(d->points) + " speeds of " + d->scene + " (commit " +
        d->commit + ", " + d->date + "; " + figures_text(d->layer) + ")");
  return lines;
}

void show_material(const MaterialLibrary& library, const std::string& name,
                   const CommandOptions& options) {
  const Material m = library.load(name);
  const auto parameters = material_parameters(m);
  nlohmann::ordered_json j{{"name", m.name}, {"description", m.description}, {"origin", m.origin}};
  auto& p = j["parameters"] = nlohmann::ordered_json::object();
  for (const auto& row : parameters) {
    nlohmann::ordered_json value;
    std::visit([&](const auto& v) { value = v; }, row.value.value);
    p[row.value.key] = {{"value", value}, {"unit", row.value.si_unit},
                        {"display", row.value.display}, {"description", row.description},
                        {"source", row.value.source}};
  }
  const std::vector<std::string> calibrated =
      m.calibration ? calibration_lines(*m.calibration) : std::vector<std::string>{};
  j["calibration"] = calibrated;
  write_json_copy(j.dump(2) + "\n", options);
  if (!options.human_output()) return;
  std::cout << m.name << ": " << m.description << "\norigin: " << m.origin << "\n";
  std::string section;
  for (const auto& row : parameters) {
    const auto dot = row.value.key.rfind('.');
    const std::string this_section = row.value.key.substr(0, dot);
    if (this_section != section) {
      section = this_section;
      std::cout << "\n[" << section << "]\n";
    }
    std::printf("  %-32s %-16s %s\n  %-32s %-16s source: %s\n",
                row.value.key.substr(dot + 1).c_str(), row.value.display.c_str(),
                row.description.c_str(), "", "", row.value.source.c_str());
  }
  std::cout << "\nCalibration (written by `feedflow calibrate`; `design` uses it and says so):\n";
  if (calibrated.empty()) std::cout << "  none\n";
  for (const auto& line : calibrated) std::cout << "  " << line << '\n';
}

}  // namespace

void add_materials_command(Command& program, int& exit_code) {
  auto args = std::make_shared<MaterialsArguments>();
  auto command = program.subcommand(
      "materials", "list the known materials, or show every parameter of one with unit and source");
  command.option("name", args->name, "material to show, e.g. loblolly_pine").type_name("NAME");
  add_json_option(command, args->options,
                  "the material list (or the named material's parameters) as JSON");
  add_verbosity_options(command, args->options, true);
  command.on_run([args, &exit_code] {
    const auto library = MaterialLibrary::standard();
    if (args->options.verbose)
      for (const auto& f : library.folders())
        std::cerr << "feedflow: material folder " << f.string() << '\n';
    if (args->name.empty())
      list_materials(library, args->options);
    else
      show_material(library, args->name, args->options);
    exit_code = 0;
  });
}

}  // namespace feedflow
