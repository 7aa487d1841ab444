#include "designer/cli/invocation.hpp"

#include <filesystem>

namespace feedflow {
namespace {
std::string& stored() {
  static std::string text;
  return text;
}
}  // namespace

void record_invocation(int argc, char** argv) {
  std::string text = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "feedflow";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool quote = arg.find_first_of(" \t'\"") != std::string::npos;
    text += " " + (quote ? "'" + arg + "'" : arg);
  }
  stored() = text;
}

const std::string& invocation() { return stored(); }

}  // namespace feedflow
