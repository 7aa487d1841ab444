#pragma once
// Loads a case file: TOML with units, overrides, range checks and cross-field checks. Any
// problem is an InputError naming the file, line and key.
#include <span>
#include <string>

#include <toml++/toml.h>

#include "designer/case/case.hpp"
#include "designer/case/material_library.hpp"

namespace feedflow {

Case load_case(const std::string& path, std::span<const SetOverride> overrides = {});
Case load_case(const std::string& path, std::span<const SetOverride> overrides,
               const MaterialLibrary& materials);

// A case file parsed once (TOML, not yet checked), for loading it many times with different
// overrides (a sweep): load_case(parsed, overrides, materials) gives what load_case(path, ...)
// gives, except that its errors name the file and key without a line (a copied table has none).
struct ParsedCase {
  std::string path;
  toml::table root;
};
ParsedCase parse_case(const std::string& path);
Case load_case(const ParsedCase& parsed, std::span<const SetOverride> overrides,
               const MaterialLibrary& materials);

// A case's one-line description and kind, without the full checks (for listings).
struct CaseSummary {
  std::string name;
  std::string kind;
  std::string description;
};
CaseSummary summarize_case(const std::string& path);

}  // namespace feedflow
