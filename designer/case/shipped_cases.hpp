#pragma once
// Where the case files shipped with feedflow (cases/) are read from.
#include <filesystem>

namespace feedflow {

// The folder holding cases/: the working folder when it has one (a checkout, or a user's copy
// they edit), else the source tree the program was built from.
std::filesystem::path shipped_case_root();

}  // namespace feedflow
