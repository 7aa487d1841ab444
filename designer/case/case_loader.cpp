#include "designer/case/case_loader.hpp"

#include <charconv>
#include <filesystem>
#include <sstream>

#include "designer/case/case_consistency.hpp"
#include "designer/case/material_reader.hpp"
#include "designer/case/table_reader.hpp"
#include "designer/case/toml_text.hpp"
#include "designer/case/written_units.hpp"
#include "models/contact/contact_law_registry.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

constexpr std::string_view kRootKeys[] = {"case", "material", "hopper", "chute",
                                           "drum", "design", "dem", "cel"};
constexpr std::string_view kCaseKeys[] = {"name", "description", "material"};
constexpr std::string_view kEquipmentKeys[] = {"hopper", "chute", "drum"};
constexpr const char* kDefaultMaterial = "loblolly_pine";

toml::table parse_case_file(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path, ec)))
    throw InputError(path, "", "no such case file (see `feedflow cases` for the shipped ones)");
  return parse_toml_text(read_input_file(path, "case file"), path);
}

// "0.5" -> number, "true" -> boolean, anything else ("32deg", "wedge") -> string.
void assign_override_value(toml::table& table, std::string_view key, const std::string& text) {
  double number = 0.0;
  const auto* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, number);
  if (!text.empty() && ec == std::errc() && ptr == end && std::isfinite(number)) {
    table.insert_or_assign(key, number);
  } else if (text == "true" || text == "false") {
    table.insert_or_assign(key, text == "true");
  } else {
    std::string s = text;
    if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front())
      s = s.substr(1, s.size() - 2);
    table.insert_or_assign(key, s);
  }
}

void apply_override(toml::table& root, const SetOverride& o) {
  std::vector<std::string> parts;
  std::stringstream split(o.key);
  for (std::string part; std::getline(split, part, '.');) {
    if (part.empty()) throw InputError("--set", o.key, "empty part in the key; write e.g. hopper.semi_angle=32deg");
    parts.push_back(part);
  }
  if (parts.size() > kMaxKeyDepth)
    throw InputError("--set", o.key.substr(0, 60), "a key nested " + std::to_string(parts.size()) +
                                                       " levels deep; feedflow's keys nest at most four");
  toml::table* table = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* next = table->get(parts[i]);
    if (!next) {
      table->insert(parts[i], toml::table{});
      next = table->get(parts[i]);
    }
    if (!next->is_table())
      throw InputError("--set", o.key, "\"" + parts[i] + "\" holds a value, not a table");
    table = next->as_table();
  }
  assign_override_value(*table, parts.back(), o.value);
}

const toml::table* table_at(const toml::table& root, std::string_view key, const std::string& file) {
  const toml::node* node = root.get(key);
  if (!node) return nullptr;
  if (!node->is_table())
    throw InputError(location(*node, file), std::string(key), "expected a table [" + std::string(key) + "]");
  return node->as_table();
}

std::string read_case_text(const toml::table& table, std::string_view key, const std::string& file) {
  const toml::node* node = table.get(key);
  if (!node) return "";
  TableContext ctx{"case", file};
  return read_text(*node, "case." + std::string(key), ctx);
}

template <class Equipment>
Equipment read_equipment(const toml::table& table, const char* name,
                         std::span<const FieldSpec<Equipment>> fields, const std::string& file,
                         std::vector<std::string>& warnings) {
  Equipment e;
  const TableContext ctx{name, file};
  read_fields(table, fields, e, ctx);
  raise_problems(check(e), table, ctx, &warnings);
  return e;
}

Material resolve_material(const toml::table& root, const toml::table* case_table,
                          const std::string& file, const MaterialLibrary& library) {
  const toml::table* material_table = table_at(root, "material", file);
  const toml::node* named = case_table ? case_table->get("material") : nullptr;
  const bool standalone = !named && material_table && material_table->contains("name");
  if (standalone) {
    Material m = read_material(*material_table, file, "case file " + file, "material");
    m.origin = file;
    return m;
  }
  std::string name = kDefaultMaterial;
  if (named) name = read_text(*named, "case.material", TableContext{"case", file});
  Material m;
  try {
    m = library.load(name);
  } catch (const InputError& e) {
    if (!e.where().empty()) throw;  // the material file itself is broken
    throw InputError(named ? location(*named, file) : file, "case.material", e.what());
  }
  if (material_table) override_material(m, *material_table, file, "case file " + file, "material");
  return m;
}

// The case in `root` (parsed from `path`; a copy of a parsed table has no line numbers, so its
// errors name the key without them) with the overrides applied, checked.
Case load_case_table(toml::table root, const std::string& path,
                     std::span<const SetOverride> overrides, const MaterialLibrary& materials);

}  // namespace

SetOverride parse_set_override(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set", text, "expected key=value, e.g. --set hopper.semi_angle=32deg");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

Case load_case(const std::string& path, std::span<const SetOverride> overrides) {
  // The case's own materials/ folder, also for a case named without a folder ("wedge.toml").
  const fs::path folder = fs::path(path).parent_path();
  return load_case(path, overrides, MaterialLibrary::standard(folder.empty() ? fs::path(".") : folder));
}

Case load_case(const std::string& path, std::span<const SetOverride> overrides,
               const MaterialLibrary& materials) {
  return load_case_table(parse_case_file(path), path, overrides, materials);
}

ParsedCase parse_case(const std::string& path) { return {path, parse_case_file(path)}; }

Case load_case(const ParsedCase& parsed, std::span<const SetOverride> overrides,
               const MaterialLibrary& materials) {
  return load_case_table(parsed.root, parsed.path, overrides, materials);
}

namespace {

Case load_case_table(toml::table root, const std::string& path,
                     std::span<const SetOverride> overrides, const MaterialLibrary& materials) {
  for (const auto& o : overrides) apply_override(root, o);

  const TableContext root_ctx{"", path};
  for (auto&& [k, node] : root) {
    require_known_key(node, k.str(), kRootKeys, root_ctx);
    table_at(root, k.str(), path);
  }

  Case c;
  c.file = path;
  c.written_units = written_units(root);
  const toml::table* case_table = table_at(root, "case", path);
  if (case_table) {
    const TableContext ctx{"case", path};
    for (auto&& [k, node] : *case_table) require_known_key(node, k.str(), kCaseKeys, ctx);
    c.name = read_case_text(*case_table, "name", path);
    c.description = read_case_text(*case_table, "description", path);
  }
  if (c.name.empty()) c.name = fs::path(path).stem().string();
  if (!overrides.empty()) {  // the file's words no longer describe what was set over them
    std::string changed;
    for (const auto& o : overrides)
      changed += (changed.empty() ? "" : ", ") + o.key + " = " + o.value;
    c.description += (c.description.empty() ? "" : "; ") + std::string("as changed: ") + changed;
  }

  std::vector<std::string_view> present;
  for (const auto key : kEquipmentKeys)
    if (root.contains(key)) present.push_back(key);
  if (present.empty())
    throw InputError(path, "", "a case needs one of the tables [hopper], [chute] or [drum]");
  if (present.size() > 1)
    throw InputError(location(*root.get(present[1]), path), std::string(present[1]),
                     "a case describes one piece of equipment, but this one has both [" +
                         std::string(present[0]) + "] and [" + std::string(present[1]) + "]");

  c.material = resolve_material(root, case_table, path, materials);

  const auto& equipment_table = *root.get(present[0])->as_table();
  if (present[0] == "hopper") {
    auto h = read_equipment(equipment_table, "hopper", hopper_fields(), path, c.warnings);
    const bool wall_from_material = !h.wall_friction_angle;
    if (wall_from_material) h.wall_friction_angle = c.material.bulk.wall_friction_angle;
    raise_problems(check_against_material(h, c.material, wall_from_material), equipment_table,
                   TableContext{"hopper", path}, &c.warnings);
    c.equipment = h;
  } else if (present[0] == "chute") {
    c.equipment = read_equipment(equipment_table, "chute", chute_fields(), path, c.warnings);
  } else {
    const auto d = read_equipment(equipment_table, "drum", drum_fields(), path, c.warnings);
    raise_problems(check_against_material(d, c.material), equipment_table, TableContext{"drum", path},
                   &c.warnings);
    c.equipment = d;
  }

  if (const toml::table* design = table_at(root, "design", path)) {
    std::vector<std::string> keys;
    TableContext ctx{"design", path};
    ctx.keys_given = &keys;
    read_fields(*design, design_target_fields(), c.design, ctx);
    raise_problems(check(c.design, c.kind(), keys), *design, ctx, &c.warnings);
  }
  if (const toml::table* dem = table_at(root, "dem", path)) {
    read_fields(*dem, dem_case_fields(), c.dem, TableContext{"dem", path});
    if (c.dem.time_step && c.dem.time_step_safety)
      raise_problems({{"time_step_safety", "give either [dem] time_step or time_step_safety, not both (the step or "
                                           "its fraction of the stable one)"}},
                     *dem, TableContext{"dem", path}, nullptr);
    try {  // k_nc needs a normal law with a K_nc branch
      choose_contact_law(c.dem.normal_law, {}, {}, c.dem.cohesion);
    } catch (const InputError&) {
      raise_problems({{"cohesion",
                       "k_nc cohesion is the hysteretic laws' K_nc branch: use it with "
                       "normal_law hysteretic_nonlinear2 or hysteretic_nonlinear1, not " +
                           c.dem.normal_law}},
                     *dem, TableContext{"dem", path}, nullptr);
    }
  }
  if (const toml::table* cel = table_at(root, "cel", path))
    read_fields(*cel, cel_case_fields(), c.cel, TableContext{"cel", path});
  return c;
}

}  // namespace

CaseSummary summarize_case(const std::string& path) {
  CaseSummary s;
  s.name = fs::path(path).stem().string();
  try {
    const toml::table root = parse_case_file(path);
    if (const toml::table* case_table = table_at(root, "case", path)) {
      if (auto name = read_case_text(*case_table, "name", path); !name.empty()) s.name = name;
      s.description = read_case_text(*case_table, "description", path);
    }
    for (const auto key : kEquipmentKeys)
      if (root.contains(key)) s.kind = std::string(key);
  } catch (const InputError& e) {
    s.description = std::string("(invalid: ") + e.what() + ")";
  }
  return s;
}

}  // namespace feedflow
