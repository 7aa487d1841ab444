#include "designer/case/toml_text.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "models/core/errors.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

// The dots of the key on one line (a [table] header or the part before '='), outside quotes.
std::size_t key_depth(std::string_view line) {
  std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string_view::npos || line[i] == '#') return 0;
  const bool header = line[i] == '[';
  std::size_t dots = 0;
  char quote = 0;
  for (; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '.') {
      ++dots;
    } else if ((header && c == ']' && i > 0 && line[i - 1] != '[') || (!header && c == '=')) {
      break;
    }
  }
  return dots;
}

}  // namespace

std::string read_input_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec && fs::is_symlink(fs::symlink_status(path, ec)))
    throw InputError(path, "", what + " is a symbolic link that leads nowhere (missing target or a loop)");
  if (fs::is_directory(status)) throw InputError(path, "", what + " is a folder, not a file");
  if (!fs::is_regular_file(status)) throw InputError(path, "", "no such " + what);
  const auto size = fs::file_size(path, ec);
  if (!ec && size > kMaxInputFileBytes)
    throw InputError(path, "", what + " of " + std::to_string(size) + " bytes; a " + what + " is a few kB (limit " +
                                   std::to_string(kMaxInputFileBytes >> 20) + " MiB)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", what + " cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

toml::table parse_toml_text(std::string_view text, const std::string& path) {
  std::size_t line = 1;
  for (std::size_t start = 0; start < text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (key_depth(text.substr(start, end - start)) >= kMaxKeyDepth)
      throw InputError(path + ":" + std::to_string(line), "",
                       "not valid here: a key nested over " + std::to_string(kMaxKeyDepth) +
                           " levels deep (feedflow's keys nest three, e.g. [material.dem.particle])");
    start = end + 1;
  }
  try {
    return toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line), "",
                     "not valid TOML: " + std::string(e.description()));
  }
}

}  // namespace feedflow
