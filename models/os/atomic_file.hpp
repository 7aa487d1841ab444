#pragma once
// Output files appear whole or not at all: written beside the target, then renamed over it.
// A run that fails half-way leaves nothing half-written.
#include <filesystem>
#include <string_view>

namespace feedflow {

// Writes `content` to `path`, creating parent folders. Throws std::runtime_error naming the
// path when the file cannot be written.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

}  // namespace feedflow
