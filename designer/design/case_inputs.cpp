#include "designer/design/case_inputs.hpp"

#include "models/core/version.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

struct DescribedInput {
  InputValue value;
  std::string_view description;
};

template <class Record>
void append(std::vector<DescribedInput>& out, const std::string& prefix,
            std::span<const FieldSpec<Record>> fields, const Record& record) {
  for (const auto& f : fields) {
    const std::string key = prefix + "." + std::string(f.key);
    if (f.is_label()) {
      const std::string& label = record.*(f.label);
      out.push_back({{key, label, "", label, ""}, f.description});
      continue;
    }
    if (f.number_list) {
      const auto& list = record.*(f.number_list);
      if (list.empty()) continue;
      std::string display;
      for (double v : list)
        display += (display.empty() ? "" : ", ") + format_number(convert_to(v, f.display_unit));
      out.push_back({{key, list, si_unit(f.dimension), display + " " + std::string(f.display_unit), ""},
                     f.description});
      continue;
    }
    double si = 0.0;
    if (f.number) {
      si = record.*(f.number);
    } else {
      const auto& optional = record.*(f.optional_number);
      if (!optional) continue;
      si = *optional;
    }
    out.push_back({{key, si, si_unit(f.dimension), format_quantity(si, f.display_unit), ""},
                   f.description});
  }
}

std::vector<DescribedInput> described_material(const Material& m) {
  std::vector<DescribedInput> out;
  append(out, "bulk", bulk_fields(), m.bulk);
  if (m.psd) append(out, "psd", psd_fields(), *m.psd);
  if (m.hypoplastic) append(out, "hypoplastic", hypoplastic_fields(), *m.hypoplastic);
  if (m.flow) append(out, "flow_properties", flow_property_fields(), *m.flow);
  if (m.surface_flow) append(out, "surface_flow", surface_flow_fields(), *m.surface_flow);
  if (m.drum_flow) append(out, "drum_flow", drum_flow_fields(), *m.drum_flow);
  if (m.dem) {
    append(out, "dem.particle", dem_particle_fields(), m.dem->particle);
    append(out, "dem.particle_particle", dem_contact_fields(), m.dem->particle_particle);
    append(out, "dem.particle_wall", dem_contact_fields(), m.dem->particle_wall);
  }
  for (auto& d : out) {
    const auto source = m.sources.find(d.value.key);
    d.value.source = source != m.sources.end() ? source->second : "feedflow default (not in the material file)";
  }
  return out;
}

// Each input the case wrote with a unit is shown in that unit ("5 t/h", not "1.389 kg/s").
void in_written_units(const Case& c, std::vector<InputValue>& inputs) {
  for (auto& in : inputs) {
    const auto written = c.written_units.find(in.key);
    if (written == c.written_units.end() || !std::holds_alternative<double>(in.value)) continue;
    try {
      if (parse_unit(written->second).dimension == parse_unit(in.si_unit).dimension)
        in.display = format_quantity(std::get<double>(in.value), written->second);
    } catch (const UnitError&) {  // a unit the display cannot take: the default display stays
    }
  }
}

}  // namespace

std::vector<MaterialParameter> material_parameters(const Material& m) {
  std::vector<MaterialParameter> out;
  for (auto& d : described_material(m))
    out.push_back({std::move(d.value), std::string(d.description)});
  return out;
}

std::vector<InputValue> case_inputs(const Case& c) {
  std::vector<DescribedInput> described;
  std::visit(
      [&](const auto& equipment) {
        using T = std::decay_t<decltype(equipment)>;
        if constexpr (std::is_same_v<T, Hopper>) append(described, "hopper", hopper_fields(), equipment);
        if constexpr (std::is_same_v<T, Chute>) append(described, "chute", chute_fields(), equipment);
        if constexpr (std::is_same_v<T, Drum>) append(described, "drum", drum_fields(), equipment);
      },
      c.equipment);
  std::vector<InputValue> out;
  for (auto& d : described) out.push_back(std::move(d.value));

  // Only the targets that belong to this kind of equipment.
  described.clear();
  append(described, "design", design_target_fields(), c.design);
  constexpr std::string_view kDesignPrefix = "design.";
  for (auto& d : described)
    if (design_target_kind(std::string_view(d.value.key).substr(kDesignPrefix.size())) == c.kind())
      out.push_back(std::move(d.value));

  out.push_back({"material.name", c.material.name, "", c.material.name, c.material.origin});
  for (auto& d : described_material(c.material)) {
    d.value.key = "material." + d.value.key;
    out.push_back(std::move(d.value));
  }
  in_written_units(c, out);
  return out;
}

std::vector<InputValue> simulation_inputs(const Case& c) {
  std::vector<DescribedInput> described;
  append(described, "dem", dem_case_fields(), c.dem);
  append(described, "cel", cel_case_fields(), c.cel);
  std::vector<InputValue> out;
  for (auto& d : described) out.push_back(std::move(d.value));
  return out;
}

void describe_case(const Case& c, DesignRecord& record) {
  record.feedflow_version = kVersion;
  record.case_name = c.name;
  record.kind = c.kind();
  record.case_file = c.file;
  record.description = c.description;
  record.inputs = case_inputs(c);
}

}  // namespace feedflow
