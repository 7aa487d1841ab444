#pragma once
// The built-in pine as calibration tests start from: its text without any [calibration] table,
// and a material read from such a text.
#include <stdexcept>
#include <string>

#include "designer/case/material_reader.hpp"
#include "models/material/builtin_materials.hpp"

namespace feedflow::testing {

inline std::string pine_text() {
  for (const auto& b : builtin_material_texts())
    if (b.name == "loblolly_pine") {
      std::string text(b.toml);
      text = text.substr(0, text.find("# Written by `feedflow calibrate`"));
      while (!text.empty() && text.back() == '\n') text.pop_back();
      return text + "\n";
    }
  throw std::runtime_error("no built-in pine");
}

inline Material read_material_text(const std::string& text) {
  return read_material(parse_material_text(text, "pine.toml"), "pine.toml", "test");
}

}  // namespace feedflow::testing
