#include "designer/case/material_reader.hpp"

#include "designer/case/calibration_reader.hpp"
#include "designer/case/table_reader.hpp"
#include "designer/case/toml_text.hpp"

namespace feedflow {
namespace {

constexpr std::string_view kTopKeys[] = {"name",  "description",     "bulk",         "psd",
                                         "hypoplastic", "flow_properties", "surface_flow",
                                         "drum_flow",   "dem",             "calibration"};
constexpr std::string_view kDemKeys[] = {"particle", "particle_particle", "particle_wall"};

const toml::table* subtable(const toml::table& parent, std::string_view key,
                            const TableContext& ctx) {
  const toml::node* node = parent.get(key);
  if (!node) return nullptr;
  if (!node->is_table())
    throw InputError(location(*node, ctx.file), ctx.dotted(key),
                     "expected a table [" + ctx.dotted(key) + "]");
  return node->as_table();
}

// Reads one section of a material. A section that the material does not have yet must be
// complete even when overriding.
class MaterialLayer {
 public:
  MaterialLayer(Material& m, const std::string& file, const std::string& default_source,
                const std::string& prefix, bool overriding)
      : material_(m), file_(file), default_source_(default_source), prefix_(prefix),
        overriding_(overriding) {}

  void read(const toml::table& table) {
    const TableContext root = context("", overriding_);
    for (auto&& [k, node] : table) require_known_key(node, k.str(), kTopKeys, root);
    if (const auto* n = table.get("name")) material_.name = read_text(*n, root.dotted("name"), root);
    if (const auto* n = table.get("description"))
      material_.description = read_text(*n, root.dotted("description"), root);
    if (material_.name.empty() && !overriding_)
      missing_key(table, root.dotted("name"), "the material's name", file_);

    const auto* bulk = subtable(table, "bulk", root);
    if (!bulk && !overriding_) missing_key(table, root.dotted("bulk"), "a [bulk] table", file_);
    if (bulk) section("bulk", *bulk, bulk_fields(), material_.bulk, overriding_);

    optional_section("psd", table, root, material_.psd, psd_fields());
    optional_section("hypoplastic", table, root, material_.hypoplastic, hypoplastic_fields());
    optional_section("flow_properties", table, root, material_.flow, flow_property_fields());
    optional_section("surface_flow", table, root, material_.surface_flow, surface_flow_fields());
    optional_section("drum_flow", table, root, material_.drum_flow, drum_flow_fields());

    if (const auto* calibration = subtable(table, "calibration", root))
      material_.calibration = read_calibration(*calibration, context("calibration", overriding_));

    if (const auto* dem = subtable(table, "dem", root)) {
      const bool complete = !material_.dem.has_value() || !overriding_;
      if (!material_.dem) material_.dem.emplace();
      const TableContext dem_ctx = context("dem", !complete);
      for (auto&& [k, node] : *dem) require_known_key(node, k.str(), kDemKeys, dem_ctx);
      read_dem_part(*dem, dem_ctx, "particle", dem_particle_fields(), material_.dem->particle,
                    complete);
      read_dem_part(*dem, dem_ctx, "particle_particle", dem_contact_fields(),
                    material_.dem->particle_particle, complete);
      read_dem_part(*dem, dem_ctx, "particle_wall", dem_contact_fields(),
                    material_.dem->particle_wall, complete);
    }
  }

 private:
  TableContext context(const std::string& section, bool overriding) {
    TableContext ctx;
    ctx.prefix = prefix_.empty() ? section : (section.empty() ? prefix_ : prefix_ + "." + section);
    ctx.file = file_;
    ctx.overriding = overriding;
    return ctx;
  }

  template <class Record>
  void section(const std::string& name, const toml::table& table,
               std::span<const FieldSpec<Record>> fields, Record& record, bool overriding) {
    TableContext ctx = context(name, overriding);
    std::map<std::string, std::string> given_sources;
    std::vector<std::string> keys;
    ctx.sources = &given_sources;
    ctx.keys_given = &keys;
    read_fields(table, fields, record, ctx);
    for (const auto& key : keys) {
      const auto found = given_sources.find(ctx.dotted(key));
      const toml::node* node = table.get(key);
      const bool from_command_line = node && node->source().begin.line == 0;
      if (overriding) material_.overridden.insert(name + "." + key);
      material_.sources[name + "." + key] =
          found != given_sources.end() ? found->second
          : from_command_line          ? std::string("command line (--set)")
                                       : default_source_;
    }
    if constexpr (requires { check(record); }) raise_problems(check(record), table, ctx, nullptr);
  }

  template <class Record>
  void optional_section(const std::string& name, const toml::table& parent,
                        const TableContext& root, std::optional<Record>& record,
                        std::span<const FieldSpec<Record>> fields) {
    const auto* table = subtable(parent, name, root);
    if (!table) return;
    const bool complete = !record.has_value() || !overriding_;
    if (!record) record.emplace();
    section(name, *table, fields, *record, !complete);
  }

  template <class Record>
  void read_dem_part(const toml::table& dem, const TableContext& dem_ctx, const std::string& part,
                     std::span<const FieldSpec<Record>> fields, Record& record, bool complete) {
    const auto* table = subtable(dem, part, dem_ctx);
    if (!table) {
      if (complete) missing_key(dem, dem_ctx.dotted(part), "a [" + dem_ctx.dotted(part) + "] table", file_);
      return;
    }
    section("dem." + part, *table, fields, record, !complete);
  }

  Material& material_;
  const std::string& file_;
  const std::string& default_source_;
  const std::string& prefix_;
  bool overriding_;
};

}  // namespace

Material read_material(const toml::table& table, const std::string& file,
                       const std::string& default_source, const std::string& prefix) {
  Material m;
  m.origin = file;
  MaterialLayer(m, file, default_source, prefix, false).read(table);
  return m;
}

void override_material(Material& material, const toml::table& table, const std::string& file,
                       const std::string& default_source, const std::string& prefix) {
  MaterialLayer(material, file, default_source, prefix, true).read(table);
}

toml::table parse_material_text(std::string_view text, const std::string& path) {
  return parse_toml_text(text, path);
}

}  // namespace feedflow
