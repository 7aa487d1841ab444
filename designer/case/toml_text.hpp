#pragma once
// Reading case and material files as TOML, with the limits a hostile or broken file meets first:
// a size cap, and a cap on how deep a key may nest (toml++ recurses once per level, and a
// [a.a.a...] header a hundred thousand levels deep overflows the stack).
#include <string>
#include <string_view>
#include <toml++/toml.h>

namespace feedflow {

inline constexpr std::size_t kMaxInputFileBytes = 4 << 20;  // 4 MiB: case and material files are a few kB
inline constexpr std::size_t kMaxKeyDepth = 32;             // [material.dem.particle] is 3

// The content of a case or material file; throws InputError naming the file when it is not a
// regular file, cannot be read or is over kMaxInputFileBytes. `what` says what the file is.
std::string read_input_file(const std::string& path, const std::string& what);

// Parses TOML text; throws InputError "file:line: not valid TOML: ..." (deep keys included).
toml::table parse_toml_text(std::string_view text, const std::string& path);

}  // namespace feedflow
