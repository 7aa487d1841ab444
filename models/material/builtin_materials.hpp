#pragma once
// The material files compiled into feedflow (cases/materials/*.toml at build time).
#include <span>
#include <string_view>

namespace feedflow {

struct BuiltinMaterialText {
  std::string_view name;  // file stem, e.g. "loblolly_pine"
  std::string_view toml;  // the file's text
};

std::span<const BuiltinMaterialText> builtin_material_texts();

}  // namespace feedflow
