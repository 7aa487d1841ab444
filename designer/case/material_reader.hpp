#pragma once
// Reads a material from a TOML table: a material file, or a case's [material] table layered
// over a named material.
#include <string>
#include <toml++/toml.h>

#include "models/material/material.hpp"

namespace feedflow {

// Reads a complete material. `file` names the source for error messages; `default_source` is
// recorded for values that carry no source of their own; `prefix` is the table's dotted path in
// its file ("" for a material file, "material" for a case's own material).
Material read_material(const toml::table& table, const std::string& file,
                       const std::string& default_source, const std::string& prefix = "");

// Applies a partial material table over `material` (a case's [material] table, `--set
// material.*`). Values given without a source are recorded as coming from `default_source`.
void override_material(Material& material, const toml::table& table, const std::string& file,
                       const std::string& default_source, const std::string& prefix);

// Parses material TOML text (a material file's content).
toml::table parse_material_text(std::string_view text, const std::string& path);

}  // namespace feedflow
