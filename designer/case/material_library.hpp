#pragma once
// Where materials come from: TOML files in material folders (the case's own materials/, then
// ./cases/materials/, then the folders of $FEEDFLOW_MATERIALS), and the materials built into
// feedflow. A file shadows a built-in material of the same name.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
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
  // Loads and checks a material; throws InputError naming the file, line and key. A material
  // loaded once is remembered by this library (and its copies): a sweep over thousands of
  // points reads each file once. Safe to call from several threads.
  Material load(const std::string& name) const;
  const std::vector<std::filesystem::path>& folders() const { return folders_; }

 private:
  Material read(const std::string& name) const;

  std::vector<std::filesystem::path> folders_;
  struct Loaded {
    std::mutex mutex;
    std::map<std::string, Material> by_name;
  };
  std::shared_ptr<Loaded> loaded_ = std::make_shared<Loaded>();
};

}  // namespace feedflow
