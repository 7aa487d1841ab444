#pragma once
// Where materials come from: TOML files in material folders (the case's own materials/, then
// ./cases/materials/, then the folders of $FEEDFLOW_MATERIALS), and the materials built into
// feedflow. A file shadows a built-in material of the same name.
#include <filesystem>
#include <string>
#include <vector>

#include "models/material/material.hpp"

namespace feedflow {

struct MaterialEntry {
  std::string name;
  std::string origin;  // file path, or "built-in"
  std::string description;
};

class MaterialLibrary {
 public:
  // Searches `folders` in order, then the built-in materials.
  explicit MaterialLibrary(std::vector<std::filesystem::path> folders);
  // The default folders: ./cases/materials and $FEEDFLOW_MATERIALS (colon-separated), with
  // `case_folder`/materials first when given.
  static MaterialLibrary standard(const std::filesystem::path& case_folder = {});

  std::vector<MaterialEntry> list() const;
  bool contains(const std::string& name) const;
  // Loads and checks a material; throws InputError naming the file, line and key.
  Material load(const std::string& name) const;
  const std::vector<std::filesystem::path>& folders() const { return folders_; }

 private:
  std::vector<std::filesystem::path> folders_;
};

}  // namespace feedflow
